import type { z } from 'zod';
import { englishReason, type Reason } from '../util/issue.ts';
import { MESH_ASSET_NAMES } from './mesh-assets.ts';
import { LIMITS } from './scene-limits.ts';

/**
 * The rules that look at more than one field, which a field's own schema cannot check.
 * They also run when other fields are broken (so that every problem is listed at once),
 * so the value they get may be half-parsed: each one checks a field before reading it.
 */

interface RuleIssue {
  path: (string | number)[];
  input: unknown;
  reason: Reason;
}

type Rule = (value: Record<string, unknown>) => RuleIssue[];

/** A rule as the function of a zod `superRefine`. */
export function asRefinement(rule: Rule) {
  return (value: Record<string, unknown>, context: z.RefinementCtx) => {
    // The reason rides along on the issue, as the error maps leave it (scene-issues.ts).
    for (const issue of rule(value)) context.addIssue({ code: 'custom', message: englishReason(issue.reason), ...issue });
  };
}

/**
 * The options of a rule's `superRefine`: run whenever the value is an object at all. zod's
 * default skips refinements once a field has the wrong type.
 */
export const alsoWhenFieldsFail = { when: (payload: z.core.ParsePayload) => isRecord(payload.value) };

/** The view direction is target − position; the same point gives no direction at all. */
export const cameraHasDirection: Rule = (camera) =>
  isSamePoint(camera.position, camera.target) ? [{ path: ['target'], input: camera.target, reason: { code: 'targetIsPosition' } }] : [];

/** `mesh` names the model of a `shape: "mesh"` object and means nothing on any other. */
export const meshOnlyOnMeshes: Rule = (object) => {
  if (object.shape === 'mesh' && object.mesh === undefined) {
    return [{ path: ['mesh'], input: undefined, reason: { code: 'meshRequired', meshes: MESH_ASSET_NAMES } }];
  }
  if (object.shape !== 'mesh' && object.mesh !== undefined) {
    return [{ path: ['mesh'], input: object.mesh, reason: { code: 'meshNotAllowed' } }];
  }
  return [];
};

/**
 * Ids are unique across objects and lights, so that an id in a goal or a ray tree means one
 * thing. Every second, third… use is reported where it stands.
 */
export const idsAreUnique: Rule = (scene) => {
  const places: { id: string; path: (string | number)[] }[] = [];
  for (const list of ['objects', 'lights']) {
    const items = scene[list];
    if (!Array.isArray(items)) continue;
    items.forEach((item: unknown, index) => {
      if (isRecord(item) && typeof item.id === 'string') places.push({ id: item.id, path: [list, index, 'id'] });
    });
  }
  const uses = new Map<string, number>();
  for (const { id } of places) uses.set(id, (uses.get(id) ?? 0) + 1);
  const seen = new Set<string>();
  return places.flatMap(({ id, path }) => {
    if (!seen.has(id)) {
      seen.add(id);
      return [];
    }
    const count = uses.get(id) ?? 0;
    return [{ path, input: id, reason: { code: 'idReused', id, uses: count } }];
  });
};

/**
 * A pixel casts s²·n²·k primary rays (supersampling, lens samples, time samples): at most
 * LIMITS.primaryRaysPerPixel (distribution-effects §1). Reported on the last factor above 1,
 * the one most likely just raised.
 */
export const primaryRaysWithinLimit: Rule = (scene) => {
  const s = wholeField(scene.settings, 'supersampling', LIMITS.supersampling);
  const n = wholeField(scene.camera, 'lensSamples', LIMITS.lensSamples);
  const k = wholeField(scene.settings, 'timeSamples', LIMITS.timeSamples);
  const rays = s * s * n * n * k;
  const [, most] = LIMITS.primaryRaysPerPixel;
  if (rays <= most) return [];
  const path = k > 1 ? ['settings', 'timeSamples'] : n > 1 ? ['camera', 'lensSamples'] : ['settings', 'supersampling'];
  const input = k > 1 ? k : n > 1 ? n : s;
  return [
    {
      path,
      input,
      reason: { code: 'tooManyRays', supersampling: s, lensSamples: n, timeSamples: k, rays, most },
    },
  ];
};

/**
 * A whole-number field of a half-parsed part, or 1 (its default) when it is missing or
 * broken: a value outside its own range is reported there, not again here.
 */
function wholeField(part: unknown, key: string, [lowest, highest]: readonly [number, number]): number {
  const value = isRecord(part) ? part[key] : undefined;
  return typeof value === 'number' && Number.isInteger(value) && value >= lowest && value <= highest ? value : 1;
}

function isSamePoint(a: unknown, b: unknown): boolean {
  return Array.isArray(a) && Array.isArray(b) && a.length === b.length && a.every((value, axis) => value === b[axis]);
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}
