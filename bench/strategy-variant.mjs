// Writes a copy of a path-mode scene with its three strategy fields set, for the Cycles
// comparisons of every combination (bench/cycles-strategies.sh, bench/cycles-agreement.sh).
//   node bench/strategy-variant.mjs FROM.json TO.json cosine|uniform true|false true|false
import { readFileSync, writeFileSync } from 'node:fs';

const [from, to, bounce, light, roulette] = process.argv.slice(2);
const scene = JSON.parse(readFileSync(from, 'utf8'));
Object.assign(scene.settings, { bounceSampling: bounce, lightSampling: light === 'true', russianRoulette: roulette === 'true' });
writeFileSync(to, JSON.stringify(scene, null, 2));
