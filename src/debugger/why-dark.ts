import type { Color, Scene } from '../scene/scene.ts';
import type { RayNode } from '../tracer/ray-tree.ts';

/**
 * "Why is it dark here?" (ray-debugger spec §2): the factors of a hit that are zero (or cut
 * a light down), as kinds with their data; the UI says them in words.
 * - background: the ray hit nothing, so it carries the background colour;
 * - shadow: S = 0, every shadow ray to the light was blocked (by `blockerId`, the nearest one);
 * - part-shadow: 0 < S < 1, an area light partly hidden (`visible` is S);
 * - facing-away: N·L = 0, the light is behind the surface;
 * - outside-cone: A = 0, the point is outside a spot light's cone (or behind an area light);
 * - weakened: 0 < A < ½, distance or the edge of a spot's cone lets only part of the light arrive;
 * - depth-limit: a mirror (a surface with ks > 0 reflects) or glass at the recursion depth
 *   sends no further ray, so its reflection (ks of the colour) or all it lets through is missing.
 */
export type DarkReason =
  | { kind: 'background' }
  | { kind: 'shadow'; lightId: string; blockerId: string | null }
  | { kind: 'part-shadow'; lightId: string; visible: number }
  | { kind: 'facing-away'; lightId: string }
  | { kind: 'outside-cone'; lightId: string }
  | { kind: 'weakened'; lightId: string; attenuation: number }
  | { kind: 'depth-limit'; maxDepth: number; objectId: string | null; glass: boolean; specular: number };

/**
 * A pixel is dark when every channel is below this share of white (below byte 77): the
 * debugger asks "why is it dark here?" only there.
 */
export const DARK_BELOW = 0.3;

export function isDark(color: Color): boolean {
  return color.every((value) => value < DARK_BELOW);
}

/** Below this A a light counts as weakened: less than half of it arrives. */
const WEAKENED_BELOW = 0.5;

export function whyDark(ray: RayNode, scene: Scene): DarkReason[] {
  if (!ray.hit) return [{ kind: 'background' }];
  const terms = ray.terms;
  if (!terms) return [];
  const reasons: DarkReason[] = [];
  for (const light of terms.lights) {
    const lightId = light.lightId;
    if (light.NdotL === 0) reasons.push({ kind: 'facing-away', lightId });
    else if (light.attenuation === 0) reasons.push({ kind: 'outside-cone', lightId });
    else if (light.visibility === 0) {
      const blocker = ray.children.find((child) => child.lightId === lightId && (child.type === 'shadow' || child.type === 'area-shadow'));
      reasons.push({ kind: 'shadow', lightId, blockerId: blocker?.objectId ?? null });
    } else {
      if (light.visibility < 1) reasons.push({ kind: 'part-shadow', lightId, visible: light.visibility });
      if (light.attenuation < WEAKENED_BELOW) reasons.push({ kind: 'weakened', lightId, attenuation: light.attenuation });
    }
  }
  if (terms.depthLimited) {
    const material = scene.objects.find((object) => object.id === ray.objectId)?.material;
    reasons.push({
      kind: 'depth-limit',
      maxDepth: scene.settings.maxDepth,
      objectId: ray.objectId,
      glass: material?.transparent ?? false,
      specular: material?.specular ?? 0,
    });
  }
  return reasons;
}
