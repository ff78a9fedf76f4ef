import { msg, str } from '@lit/localize';
import { lightSamples, type DebugStep, type StepPlace } from '../../../debugger/debug-steps.ts';
import type { TermKind } from '../../../debugger/debug-equation.ts';
import type { PseudocodeLine } from '../../../debugger/pseudocode.ts';
import type { DarkReason } from '../../../debugger/why-dark.ts';
import type { Scene } from '../../../scene/scene.ts';
import type { RayNode } from '../../../tracer/ray-tree.ts';
import { localNumbers } from '../../../i18n/number-format.ts';
import { rayName } from '../traced-ray-text.ts';
import { itemName as sceneItemName } from '../scene-names.ts';

const share = localNumbers({ maximumFractionDigits: 2 });
const fraction = localNumbers({ maximumSignificantDigits: 3 });

/** The ray debugger's words (translated); the formulas stay in the symbols of the shading model. */

/** One line of the pseudocode, as the tracer's steps read. */
export function pseudocodeText(line: PseudocodeLine): string {
  switch (line) {
    case 'sample-loop':
      return msg('for each sample of the pixel:');
    case 'lens-loop':
      return msg('for each lens point and each moment (a pinhole camera has one of each):');
    case 'trace-primary':
      return msg('colour ← trace(primary ray through it, depth 0)');
    case 'average':
      return msg('pixel ← Σ share · colour of all these rays');
    case 'trace':
      return msg('trace(ray, depth):');
    case 'nearest-hit':
      return msg('find the nearest hit; nothing hit: return the background');
    case 'ambient':
      return msg('colour ← ka·C + Σ la·Lc·C');
    case 'light-loop':
      return msg('for each light (an area light: each of its samples, with I ÷ their number):');
    case 'shadow-ray':
      return msg('if N·L > 0, A > 0 and Shadows is on: cast a shadow ray toward the light');
    case 'blocked':
      return msg('blocked: S = 0, the light adds nothing');
    case 'lit':
      return msg('reaches it: colour += I·A·(N·L·kd·ld·Lc·C + (R·V)ⁿ·ks·ls·Lc)');
    case 'mirror':
      return msg('opaque with ks > 0, below the maximum depth: colour += ks·trace(reflected ray, depth + 1)');
    case 'schlick':
      return msg('glass, below the maximum depth: kr ← Schlick, kt ← 1 − kr');
    case 'glass':
      return msg('colour += kt·trace(refracted ray) + kr·trace(reflected ray)');
    case 'glossy':
      return msg('rough: m×m rays around each of these, each with 1/m² of its weight');
    case 'return':
      return msg('return clamp(colour, 0, 1)');
  }
}

/** What the learner reads for an object or light id (its name in the reader's language), or '' for none. */
export function itemName(scene: Scene, id: string | null): string {
  return id === null ? '' : sceneItemName(scene, id);
}

/** The term's name in the equation. */
export function termName(kind: TermKind, light: string): string {
  switch (kind) {
    case 'ambient':
      return msg('Ambient');
    case 'light-ambient':
      return msg(str`Ambient of ${light}`);
    case 'diffuse':
      return msg(str`Diffuse from ${light}`);
    case 'specular':
      return msg(str`Highlight from ${light}`);
    case 'refract':
      return msg('Refracted ray');
    case 'reflect':
      return msg('Reflected ray');
  }
}

/**
 * A share of the pixel: a fraction 1/N when it is one (1/4 for one of 2×2 samples, 1/36 for
 * one of 3×3 light samples of it), else a decimal number.
 */
export function shareText(value: number): string {
  const inverse = 1 / value;
  if (value > 0 && Math.abs(inverse - Math.round(inverse)) < 1e-9 * inverse) return Math.round(inverse) === 1 ? '1' : `1/${Math.round(inverse)}`;
  return fraction.format(value);
}

/** "Sample 2 of 4", "Lens point 3 of 9"…: where a ray sits among its siblings. */
export function placeText(place: StepPlace): string {
  const { index, count } = place;
  switch (place.of) {
    case 'sample':
      return msg(str`Sample ${index} of ${count}`);
    case 'lens':
      return msg(str`Lens point ${index} of ${count}`);
    case 'moment':
      return msg(str`Moment ${index} of ${count}`);
    case 'light':
      return msg(str`Light sample ${index} of ${count}`);
    case 'glossy':
      return msg(str`Ray ${index} of ${count}`);
  }
}

/** How many lens points and moments a sample's rays come from. */
export function lensAndMoments(root: RayNode): { lensPoints: number; moments: number } {
  const lensPoints = new Set(root.children.map((child) => child.lensPoint?.join(' '))).size;
  return { lensPoints, moments: root.children.length / Math.max(lensPoints, 1) };
}

/** The name of the step's ray with its place: "Reflected ray", "Lens point 3 of 9", "Moment 2 of 4 (τ = 0.38)"… */
export function rayLabel(step: DebugStep): string {
  const ray = step.ray;
  if (!ray) return '';
  const place = step.place;
  if (!place) return rayName(ray);
  if (place.of === 'moment' && ray.time !== undefined) return msg(str`${placeText(place)} (τ = ${share.format(ray.time)})`);
  if (place.of === 'sample' || place.of === 'lens' || place.of === 'moment') return placeText(place);
  const name = rayName(ray);
  return msg(str`${name} (${place.index} of ${place.count})`);
}

/** The step as one short row of the debugger's tree. */
export function treeLabel(step: DebugStep, scene: Scene): string {
  const ray = step.ray;
  if (step.kind === 'lens' && step.place) return placeText(step.place);
  if (!ray || step.kind === 'average') return msg('The pixel: Σ share · colour');
  const object = itemName(scene, ray.objectId);
  switch (step.kind) {
    case 'sample':
      return step.place ? msg(str`${placeText(step.place)}: ${ray.children.length} rays`) : msg(str`The sample: ${ray.children.length} rays`);
    case 'cast':
      if (ray.absorbed) return msg(str`${rayLabel(step)}: into the surface, black`);
      return ray.hit ? `${rayLabel(step)} → ${object}` : msg(str`${rayLabel(step)} → nothing`);
    case 'shade':
      return msg('Ambient: ka·C + Σ la·Lc·C');
    case 'light': {
      const light = itemName(scene, ray.lightId);
      const who = step.place ? msg(str`${light}, sample ${step.place.index} of ${step.place.count}`) : light;
      if (ray.type === 'shadow' || ray.type === 'area-shadow') return msg(str`Shadow ray → ${who}: blocked by ${object || msg('an object')}`);
      if (ray.untested) return msg(str`Direction → ${who}: not tested`);
      return msg(str`Shadow ray → ${who}: reaches it`);
    }
    case 'split': {
      if (totallyReflected(ray)) return msg('Total internal reflection: kr 1, kt 0');
      const terms = ray.terms;
      return msg(str`Schlick: kr ${share.format(terms?.reflect?.weight ?? 0)}, kt ${share.format(terms?.refract?.weight ?? 0)}`);
    }
    case 'return':
      if (!ray.hit) return msg('Returns the background colour');
      return step.adds.some((value) => value !== 0) ? msg('Returns its colour, clamped') : msg('Returns its colour');
    case 'lens':
      return '';
  }
}

/** A glass hit whose ray is refracted nowhere: beyond the critical angle all of it is reflected (Snell's law has no solution). */
function totallyReflected(hit: RayNode): boolean {
  return !hit.children.some((child) => child.type === 'refract');
}

/** The first sentence for a sample that casts several rays: where they leave from and aim. */
function sampleText(root: RayNode): string {
  const { lensPoints, moments } = lensAndMoments(root);
  const rays = root.children.length;
  if (lensPoints > 1 && moments > 1)
    return msg(
      str`This sample casts ${rays} rays: ${lensPoints} points of the lens, each at ${moments} moments while the shutter is open, all aimed at F, where its pinhole ray meets the plane in focus.`,
    );
  if (lensPoints > 1)
    return msg(str`This sample casts ${rays} rays from ${lensPoints} points of the lens, all aimed at F, where its pinhole ray meets the plane in focus.`);
  return msg(str`This sample casts ${rays} rays at ${moments} moments while the shutter is open.`);
}

/** One sentence (or two) for the step, read out to screen readers as the cursor moves. */
export function stepText(step: DebugStep, scene: Scene): string {
  const ray = step.ray;
  const counts = msg(str`It counts ${shareText(step.share)} of the pixel.`);
  if (step.kind === 'lens' && step.place)
    return `${msg(str`${placeText(step.place)}: its rays start from the same point of the lens, one at each moment.`)} ${counts}`;
  if (!ray || step.kind === 'average') return msg('The pixel’s colour is the sum of its rays’ colours, each times its share.');
  const kind = rayLabel(step);
  const object = itemName(scene, ray.objectId);
  const light = itemName(scene, ray.lightId);
  switch (step.kind) {
    case 'sample':
      return `${step.place ? `${placeText(step.place)}. ` : ''}${sampleText(ray)} ${counts}`;
    case 'cast':
      if (ray.absorbed) return msg(str`${kind} points into the surface: it is not traced and adds black.`);
      return `${ray.hit ? msg(str`${kind} at depth ${step.depth} hits ${object}.`) : msg(str`${kind} at depth ${step.depth} hits nothing.`)} ${msg(str`Its colour counts ${shareText(step.share)} of the pixel.`)}`;
    case 'shade':
      return msg(str`Shading the hit on ${object}: ambient first.`);
    case 'light': {
      const sample = step.place ? `${placeText(step.place)}: ` : '';
      if (ray.type === 'shadow' || ray.type === 'area-shadow')
        return sample + msg(str`The shadow ray to ${light} is blocked by ${object || msg('an object')}: S = 0.`);
      if (ray.untested)
        return sample + msg(str`Shadows is off: no shadow ray is cast, so ${light} counts as reaching the point: its diffuse and highlight are added.`);
      if (step.place)
        return sample + msg(str`The shadow ray to ${light} reaches it: this sample’s diffuse and highlight (1/${lightSamples(step)} of the light) are added.`);
      return msg(str`The shadow ray to ${light} reaches it: its diffuse and highlight are added.`);
    }
    case 'split':
      if (totallyReflected(ray))
        return msg(
          'Glass, but the ray is inside and meets the surface beyond the critical angle: no ray is refracted, all of it is reflected (total internal reflection).',
        );
      return msg(str`Glass: Schlick splits the colour between the refracted and the reflected ray.`);
    case 'return':
      if (!ray.hit) return msg('Nothing hit: the ray returns the background colour.');
      if (step.adds.some((value) => value !== 0))
        return msg(str`The hit on ${object} returns its colour, clamped to 0..1: clamping lowers it, so the pixel’s sum drops.`);
      return msg(str`The hit on ${object} returns its colour, clamped to 0..1.`);
    case 'lens':
      return '';
  }
}

function lightType(scene: Scene, id: string): Scene['lights'][number]['type'] | undefined {
  return scene.lights.find((light) => light.id === id)?.type;
}

/** "Why is it dark here?", one reason in words. */
export function darkReasonText(reason: DarkReason, scene: Scene): string {
  switch (reason.kind) {
    case 'background':
      return msg('The ray hit nothing, so it brings back the background colour.');
    case 'shadow':
      return reason.blockerId
        ? msg(str`In shadow: ${itemName(scene, reason.blockerId)} is between the point and ${itemName(scene, reason.lightId)} (S = 0).`)
        : msg(str`In shadow: something is between the point and ${itemName(scene, reason.lightId)} (S = 0).`);
    case 'part-shadow':
      return msg(
        str`Partly in shadow: only ${Math.round(reason.visible * 100)}% of ${itemName(scene, reason.lightId)} is visible (S = ${share.format(reason.visible)}).`,
      );
    case 'facing-away':
      return msg(str`The surface faces away from ${itemName(scene, reason.lightId)} (N·L = 0).`);
    case 'outside-cone':
      // A spot light's cone; an area light shines to one side of its panel only (half-angle 90°).
      return lightType(scene, reason.lightId) === 'area'
        ? msg(str`The point is behind ${itemName(scene, reason.lightId)}, which shines to one side only (A = 0).`)
        : msg(str`The point is outside the cone of ${itemName(scene, reason.lightId)} (A = 0).`);
    case 'weakened': {
      const light = itemName(scene, reason.lightId);
      const attenuation = share.format(reason.attenuation);
      // A = distance factor × angle factor: a point light has only the first (attenuation.ts).
      switch (lightType(scene, reason.lightId)) {
        case 'point':
          return msg(str`Only part of ${light} arrives: A = ${attenuation} (its distance).`);
        case 'area':
          return msg(
            str`Only part of ${light} arrives: A = ${attenuation} (distance, or the point lies off to the side of the panel, which shines most straight ahead).`,
          );
        default:
          return msg(str`Only part of ${light} arrives: A = ${attenuation} (distance or the edge of its cone).`);
      }
    }
    case 'depth-limit': {
      const object = itemName(scene, reason.objectId);
      return reason.glass
        ? msg(
            str`The recursion depth (${reason.maxDepth}) is reached: ${object} is glass, but no refracted or reflected ray is traced, so what it lets through is missing.`,
          )
        : msg(
            str`The recursion depth (${reason.maxDepth}) is reached: ${object} reflects (ks = ${share.format(reason.specular)}), but no reflected ray is traced, so that part of its colour is missing.`,
          );
    }
  }
}
