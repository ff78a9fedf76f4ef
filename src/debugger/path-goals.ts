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

/**
 * Where "show me" takes the path debugger for a task's `debugger.stepped` (the path and the
 * vertex): the first vertex, path by path, whose arriving ray has every field of `want`;
 * failing that (another pixel, a changed scene), the first ray of its kind; the camera for a
 * step with no ray. Null when no path shown has such a ray.
 */
export function findPathVertex(paths: readonly RecordedPath[], want: Partial<DebuggerRay> | null): { path: number; vertex: number } | null {
  if (paths.length === 0) return null;
  if (!want) return { path: 0, vertex: 0 };
  const matching = (fields: Partial<DebuggerRay>) => {
    for (let path = 0; path < paths.length; path++) {
      for (let vertex = 1; vertex < paths[path].vertices.length; vertex++) {
        const ray = pathRayOf(paths[path], vertex);
        if (ray && Object.entries(fields).every(([field, value]) => ray[field as keyof DebuggerRay] === value)) return { path, vertex };
      }
    }
    return null;
  };
  return matching(want) ?? (want.type ? matching({ type: want.type }) : null);
}
