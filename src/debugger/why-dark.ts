import type { Scene } from '../scene/scene.ts';
import type { RayNode } from '../tracer/ray-tree.ts';

/**
 * "Why is it dark here?" (ray-debugger spec §2): the factors of a hit that are zero (or cut
 * a light down), as kinds with their data; the UI says them in words.
 * - background: the ray hit nothing, so it carries the background colour;
 * - shadow: S = 0, every shadow ray to the light was blocked (by `blockerId`, the nearest one);
 * - part-shadow: 0 < S < 1, an area light partly hidden (`visible` is S);
 * - facing-away: N·L = 0, the light is behind the surface;
 * - outside-cone: A = 0, the point is outside a spot light's cone (or behind an area light);
 * - depth-limit: a mirror or glass at the recursion depth sends no further ray.
 */
export type DarkReason =
  | { kind: 'background' }
  | { kind: 'shadow'; lightId: string; blockerId: string | null }
  | { kind: 'part-shadow'; lightId: string; visible: number }
  | { kind: 'facing-away'; lightId: string }
  | { kind: 'outside-cone'; lightId: string }
  | { kind: 'depth-limit'; maxDepth: number };

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
    } else if (light.visibility < 1) reasons.push({ kind: 'part-shadow', lightId, visible: light.visibility });
  }
  if (terms.depthLimited) reasons.push({ kind: 'depth-limit', maxDepth: scene.settings.maxDepth });
  return reasons;
}
