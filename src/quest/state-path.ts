/**
 * Paths into the lab state (and into an action), as goals write them:
 *
 *   scene.settings.supersampling          a field of a field
 *   scene.camera.pixels[0]                an item of a list by position (from 0)
 *   scene.objects[id=ball].material.color an item of a list by its `id`
 *   scene.objects.length                  how many items a list has
 *
 * Positions change when an object is added or deleted; ids do not, so goals select scene
 * objects and lights by id. A path that leads nowhere (no item with that id, a field of
 * `null`) reads as `undefined` rather than failing: "the ball is red" is simply false while
 * there is no ball.
 */

import { isRecord } from '../util/is-record.ts';
import type { PlainType, Reason } from '../util/issue.ts';

export type PathStep = { kind: 'field'; name: string } | { kind: 'index'; index: number } | { kind: 'id'; id: string };

export type ParsedPath = { ok: true; steps: PathStep[] } | { ok: false; reason: Reason };

const FIRST_FIELD = /[A-Za-z_][A-Za-z0-9_]*/y;
const NEXT_STEP = /\.([A-Za-z_][A-Za-z0-9_]*)|\[([0-9]+)\]|\[id=([^\]]+)\]/y;

export function parsePath(text: string): ParsedPath {
  FIRST_FIELD.lastIndex = 0;
  const first = FIRST_FIELD.exec(text);
  if (!first) return { ok: false, reason: { code: 'pathStart', path: text } };
  const steps: PathStep[] = [{ kind: 'field', name: first[0] }];
  let offset = FIRST_FIELD.lastIndex;
  while (offset < text.length) {
    NEXT_STEP.lastIndex = offset;
    const step = NEXT_STEP.exec(text);
    if (!step) {
      return { ok: false, reason: { code: 'pathUnreadable', path: text, rest: text.slice(offset) } };
    }
    const [, name, index, id] = step;
    if (name !== undefined) steps.push({ kind: 'field', name });
    else if (index !== undefined) steps.push({ kind: 'index', index: Number(index) });
    else steps.push({ kind: 'id', id });
    offset = NEXT_STEP.lastIndex;
  }
  return { ok: true, steps };
}

/** Paths are read on every action, so each is parsed once. */
const parsedPaths = new Map<string, PathStep[] | undefined>();

/** The value at `path` in `root`, or undefined when there is none. */
export function readPath(root: unknown, path: string): unknown {
  if (!parsedPaths.has(path)) {
    const parsed = parsePath(path);
    parsedPaths.set(path, parsed.ok ? parsed.steps : undefined);
  }
  const steps = parsedPaths.get(path);
  if (!steps) return undefined;
  let value = root;
  for (const step of steps) {
    value = takeStep(value, step);
    if (value === undefined) return undefined;
  }
  return value;
}

function takeStep(value: unknown, step: PathStep): unknown {
  if (step.kind === 'index') return Array.isArray(value) ? value[step.index] : undefined;
  if (step.kind === 'id') return Array.isArray(value) ? value.find((item) => isRecord(item) && item.id === step.id) : undefined;
  if ((Array.isArray(value) || typeof value === 'string') && step.name === 'length') return value.length;
  return isRecord(value) && Object.hasOwn(value, step.name) ? value[step.name] : undefined;
}

/** Fields an object or light may leave out, so a sample may not show them. */
const OPTIONAL_FIELDS = new Set(['name', 'mesh']);

/**
 * Why `path` cannot be a path into values shaped like `sample`, or undefined when it can.
 * Catches misspelt fields when a level loads. What the sample cannot show is accepted: an
 * id that is not in it (the learner may add that object later), a position past its end,
 * anything below a `null`.
 */
export function problemWithPath(path: string, sample: unknown): Reason | undefined {
  const parsed = parsePath(path);
  if (!parsed.ok) return parsed.reason;
  let value = sample;
  let place = '';
  for (const step of parsed.steps) {
    if (value === null || value === undefined) return undefined;
    if (step.kind === 'field') {
      if (Array.isArray(value) && step.name !== 'length') return { code: 'pathIsList', place, field: step.name };
      if (isRecord(value) && !Object.hasOwn(value, step.name)) {
        if (OPTIONAL_FIELDS.has(step.name)) return undefined;
        return { code: 'pathNoField', field: step.name, place, fields: Object.keys(value) };
      }
      // The lab's state is JSON-like: below an object or a list there are only these.
      if (!Array.isArray(value) && !isRecord(value)) return { code: 'pathNotObject', place, type: typeof value as PlainType, field: step.name };
    } else if (!Array.isArray(value)) {
      return { code: 'pathNotList', place, step: step.kind === 'index' ? `[${step.index}]` : `[id=${step.id}]` };
    }
    value = takeStep(value, step);
    place += step.kind === 'field' ? `${place === '' ? '' : '.'}${step.name}` : step.kind === 'index' ? `[${step.index}]` : `[id=${step.id}]`;
  }
  return undefined;
}
