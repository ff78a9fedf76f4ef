// The figure of level 22 (Monte Carlo noise): the error of this tracer's path-traced pictures
// of the level's room against the paths per pixel N, on log–log axes beside the 1/√N line.
// `npx tsx scripts/path-noise-figure.ts` renders the room small (48 × 48) at N = 1, 4, 16, 64
// and 256 and once at 4096 as the reference, and writes assets/figures/path-noise-error.svg.
// The error is the root-mean-square difference from the reference over every pixel and
// channel, each picture with its own seed so that no two share their random paths. The
// dashed line is c/√N through the N = 1 point: the standard error of a mean of N independent
// estimates (pbrt-v4 §2.1.3). The reference has its own noise (about 1/√(4096/N) of the
// picture's), so the measured points lie at most ~3 % above the true error at N = 256.
import { readFileSync, writeFileSync } from 'node:fs';
import { loadLevels } from '../src/quest/level-index.ts';
import type { Scene } from '../src/scene/scene.ts';
import { renderTile } from '../src/tracer/render-tile.ts';
import { buildTracerScene } from '../src/tracer/tracer-scene.ts';

const LEVEL = '22-monte-carlo-noise';
const SIZE = 48;
const COUNTS = [1, 4, 16, 64, 256];
const REFERENCE_PATHS = 4096;
const OUT = 'assets/figures/path-noise-error.svg';

const catalog = loadLevels(readFileSync('levels/index.json', 'utf8'), (name) => readFileSync(`levels/${name}`, 'utf8'));
const level = catalog.chapters.flatMap((chapter) => chapter.entries).find((entry) => entry.id === LEVEL);
if (!level?.ok) throw new Error(`${LEVEL} did not load: ${JSON.stringify(level?.ok === false ? level.errors : 'missing')}`);

function render(scene: Scene, paths: number, seed: number): Float32Array {
  const tracer = buildTracerScene({ ...scene, settings: { ...scene.settings, pathSamples: paths, imageSize: [SIZE, SIZE] } }, new Map());
  return renderTile(tracer, { x: 0, y: 0, width: SIZE, height: SIZE }, { imageWidth: SIZE, imageHeight: SIZE, seed });
}

function rmsError(picture: Float32Array, reference: Float32Array): number {
  let sum = 0;
  for (let i = 0; i < picture.length; i++) sum += (picture[i]! - reference[i]!) ** 2;
  return Math.sqrt(sum / picture.length);
}

const scene = level.level.scene;
const reference = render(scene, REFERENCE_PATHS, 1000);
const errors = COUNTS.map((n, i) => rmsError(render(scene, n, i + 1), reference));
for (const [i, n] of COUNTS.entries()) console.log(`N = ${n}: error ${errors[i]!.toExponential(3)}`);

// Log–log axes: N from 1 to 256 left to right; the error axis spans the measured errors, in half decades.
const [left, right, top, bottom] = [78, 400, 22, 236];
const logMax = Math.ceil(Math.log10(errors[0]! * 1.2) * 2) / 2;
const logMin = Math.floor(Math.log10(Math.min(...errors) / 1.5) * 2) / 2;
const x = (n: number) => left + ((right - left) * Math.log(n)) / Math.log(256);
const y = (error: number) => top + ((bottom - top) * (logMax - Math.log10(error))) / (logMax - logMin);
const line = (n: number) => errors[0]! / Math.sqrt(n);
const ticksY: number[] = [];
for (let e = Math.ceil(logMin); e <= Math.floor(logMax); e++) ticksY.push(e);
const svg = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 440 280" width="440" height="280">
  <!--
    Made by scripts/path-noise-figure.ts from this tracer's renders of level ${LEVEL}'s room
    (${SIZE} × ${SIZE}, against ${REFERENCE_PATHS} paths per pixel): the dots are the measured
    root-mean-square error at N = ${COUNTS.join(', ')}; the dashed line is 1/√N through the first
    dot. Both axes are logarithmic. Only numbers and N are written, so the figure serves every
    language; mid-tone colours read on the light and the dark theme alike.
  -->
  <path d="M${left} ${top}V${bottom}H${right}" fill="none" stroke="#868e96" stroke-width="3" />
${COUNTS.map((n) => `  <path d="M${x(n).toFixed(1)} ${bottom}v8" stroke="#868e96" stroke-width="2" />\n  <text x="${x(n).toFixed(1)}" y="${bottom + 34}" fill="#868e96" font-family="sans-serif" font-size="24" text-anchor="middle">${n}</text>`).join('\n')}
${ticksY.map((e) => `  <path d="M${left - 8} ${y(10 ** e).toFixed(1)}h8" stroke="#868e96" stroke-width="2" />\n  <text x="${left - 12}" y="${(y(10 ** e) + 8).toFixed(1)}" fill="#868e96" font-family="sans-serif" font-size="22" text-anchor="end">10<tspan dy="-10" font-size="16">${e}</tspan></text>`).join('\n')}
  <text x="${right + 8}" y="${bottom + 6}" fill="#868e96" font-family="Georgia, serif" font-size="26" font-style="italic">N</text>
  <path d="M${x(1).toFixed(1)} ${y(line(1)).toFixed(1)}L${x(256).toFixed(1)} ${y(line(256)).toFixed(1)}" stroke="#f08c00" stroke-width="3" stroke-dasharray="10 7" />
  <text x="${x(32).toFixed(1)}" y="${(y(line(32)) + 34).toFixed(1)}" fill="#f08c00" font-family="Georgia, serif" font-size="26" font-style="italic" text-anchor="end">1/√N</text>
${COUNTS.map((n, i) => `  <circle cx="${x(n).toFixed(1)}" cy="${y(errors[i]!).toFixed(1)}" r="9" fill="#1c7ed6" />`).join('\n')}
</svg>
`;
writeFileSync(OUT, svg);
console.log(`wrote ${OUT}`);
