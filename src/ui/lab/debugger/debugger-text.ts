import { msg, str } from '@lit/localize';
import type { DebugStep } from '../../../debugger/debug-steps.ts';
import type { TermKind } from '../../../debugger/debug-equation.ts';
import type { PseudocodeLine } from '../../../debugger/pseudocode.ts';
import type { DarkReason } from '../../../debugger/why-dark.ts';
import type { Scene } from '../../../scene/scene.ts';
import { localNumbers } from '../../../i18n/number-format.ts';
import { rayName } from '../ray-names.ts';
import { itemName as sceneItemName } from '../scene-names.ts';

const share = localNumbers({ maximumFractionDigits: 2 });

/** The ray debugger's words (translated); the formulas stay in the symbols of the shading model. */

/** One line of the pseudocode, as the tracer's steps read. */
export function pseudocodeText(line: PseudocodeLine): string {
  switch (line) {
    case 'sample-loop':
      return msg('for each sample of the pixel:');
    case 'trace-primary':
      return msg('colour ← trace(primary ray through it, depth 0)');
    case 'average':
      return msg('pixel ← average of the samples’ colours');
    case 'trace':
      return msg('trace(ray, depth):');
    case 'nearest-hit':
      return msg('find the nearest hit; nothing hit: return the background');
    case 'ambient':
      return msg('colour ← ka·C + Σ la·Lc·C');
    case 'light-loop':
      return msg('for each light (each sample of an area light):');
    case 'shadow-ray':
      return msg('if Shadows is on: cast a shadow ray toward the light');
    case 'blocked':
      return msg('blocked: S = 0, the light adds nothing');
    case 'lit':
      return msg('reaches it: colour += I·A·(N·L·kd·ld·Lc·C + (R·V)ⁿ·ks·ls·Lc)');
    case 'mirror':
      return msg('mirror, depth < max: colour += ks·trace(reflected ray, depth + 1)');
    case 'schlick':
      return msg('glass, depth < max: kr ← Schlick, kt ← 1 − kr');
    case 'glass':
      return msg('colour += kt·trace(refracted ray) + kr·trace(reflected ray)');
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

/** One sentence for the step, read out to screen readers as the cursor moves. */
export function stepText(step: DebugStep, scene: Scene): string {
  const ray = step.ray;
  if (!ray) return msg('The pixel’s colour is the average of its samples’ colours.');
  const kind = rayName(ray);
  const object = itemName(scene, ray.objectId);
  const light = itemName(scene, ray.lightId);
  switch (step.kind) {
    case 'cast':
      return ray.hit ? msg(str`${kind} at depth ${step.depth} hits ${object}.`) : msg(str`${kind} at depth ${step.depth} hits nothing.`);
    case 'shade':
      return msg(str`Shading the hit on ${object}: ambient first.`);
    case 'light':
      if (ray.type === 'shadow' || ray.type === 'area-shadow') return msg(str`The shadow ray to ${light} is blocked by ${object || msg('an object')}: S = 0.`);
      if (ray.untested) return msg(str`Shadows is off: no shadow ray is cast, so ${light} counts as reaching the point: its diffuse and highlight are added.`);
      return msg(str`The shadow ray to ${light} reaches it: its diffuse and highlight are added.`);
    case 'split':
      return msg(str`Glass: Schlick splits the colour between the refracted and the reflected ray.`);
    case 'return':
      return ray.hit ? msg(str`The hit on ${object} returns its colour, clamped to 0..1.`) : msg('Nothing hit: the ray returns the background colour.');
    case 'average':
      return msg('The pixel’s colour is the average of its samples’ colours.');
  }
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
      return msg(str`Partly in shadow: only ${Math.round(reason.visible * 100)}% of ${itemName(scene, reason.lightId)} is visible (S = ${share.format(reason.visible)}).`);
    case 'facing-away':
      return msg(str`The surface faces away from ${itemName(scene, reason.lightId)} (N·L = 0).`);
    case 'outside-cone':
      return msg(str`The point is outside the cone of ${itemName(scene, reason.lightId)} (A = 0).`);
    case 'depth-limit':
      return msg(str`The recursion depth (${reason.maxDepth}) is reached: this mirror or glass sends no further ray.`);
  }
}
