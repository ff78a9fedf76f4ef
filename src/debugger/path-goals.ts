import type { DebuggerRay } from '../lab-state/lab-action.ts';
import type { RecordedPath } from '../tracer/path-recorder.ts';

/**
 * The path debugger as the quest engine sees it (docs/levels.md, `debugger.stepped`): at
 * vertex `vertex` of a path, the ray that arrived there, in the Whitted debugger's terms —
 * the camera ray is `primary`, a bounce `reflect` (diffuse, mirror, glass reflected) or
 * `refract` (glass refracted), as the 3D view draws them (view/path-focus.ts); its depth is
 * the number of bounces before it. At the camera no ray has been cast yet: null.
 */
export function pathRayOf(path: RecordedPath, vertex: number): DebuggerRay | null {
  const from = path.vertices[vertex - 1];
  const to = path.vertices[vertex];
  if (!from || !to) return null;
  return {
    type: vertex === 1 ? 'primary' : from.event === 'glass-refract' ? 'refract' : 'reflect',
    depth: vertex - 1,
    hit: to.event !== 'escaped',
    objectId: to.objectId,
    lightId: to.lightId,
    from: from.objectId,
  };
}
