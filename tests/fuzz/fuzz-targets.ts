import fc from 'fast-check';
import { readdirSync, readFileSync } from 'node:fs';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { decodeAssignment, LINK_PREFIX, LINK_VERSION } from '../../src/classroom/assignment-link.ts';
import { readExportFile } from '../../src/classroom/dashboard-read-file.ts';
import { parseSurvey } from '../../src/classroom/survey-schema.ts';
import { decodeSceneLink, SCENE_LINK_PREFIX } from '../../src/app/scene-link.ts';
import { levelFileName, loadLevels } from '../../src/quest/level-index.ts';
import { parseLevelJson } from '../../src/quest/level-schema.ts';
import { exportProgress, parseProgressJson } from '../../src/quest/progress-store.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { parseSceneJson } from '../../src/scene/scene-schema.ts';
import { toBase64Url } from '../../src/util/base64url.ts';
import { issueLine, type Issue } from '../../src/util/issue.ts';
import { isRecord } from '../../src/util/is-record.ts';
import { readJson } from '../../src/util/read-json.ts';
import { deflate } from '../../src/util/zlib-bytes.ts';
import { simulatedExport } from '../support/class-exports.ts';
import { FakeClock, levelWithId } from '../support/quest-fixtures.ts';

/**
 * Every parser of outside input, fed generated input: valid files with one part replaced,
 * removed or repeated many times, files cut short, random JSON and random text. A parser
 * must accept, or refuse with reasons; it must never throw or take long. Shared by the
 * suite (about 1,000 cases each) and `npm run fuzz` (10,000 each, with a table).
 */

/** What one case came to: a clean refusal (a list of reasons), an acceptance, or a crash (a throw or a malformed result). */
export type Outcome = 'accepted' | 'refused' | 'crashed';

/** One case: the text of a file, or (`raw`) the text as it is for a link or a CSV file instead of the JSON inside. */
export interface FuzzInput {
  text: string;
  raw: boolean;
}

export interface FuzzTarget {
  name: string;
  /** A valid input (parsed JSON) that the cases vary. */
  sample: unknown;
  run(input: FuzzInput): Promise<Outcome>;
}

/** A case slower than this counts as a hang. */
export const HANG_MS = 1000;

const levelsFolder = new URL('../../levels/', import.meta.url);
const levelFiles = new Map(readdirSync(levelsFolder).map((name) => [name, readFileSync(new URL(name, levelsFolder), 'utf8')]));
const firstLevel = JSON.parse(levelFiles.get('01-introduction.level.json') ?? '{}') as unknown;
const defaultSurvey = JSON.parse(readFileSync(new URL('../../src/classroom/surveys/default.survey.json', import.meta.url), 'utf8')) as unknown;

/** A reason line, or an issue (src/util/issue.ts) whose English line says something. */
const isReason = (reason: unknown) =>
  typeof reason === 'string'
    ? reason.length > 0
    : isRecord(reason) && typeof reason.path !== 'undefined' && isRecord(reason.reason) && issueLine(reason as unknown as Issue).length > 0;
const isReasons = (value: unknown) => Array.isArray(value) && value.length > 0 && value.every(isReason);

/** A parse result of the `{ ok, errors }` shape, judged. */
function judged(result: { ok: boolean; errors?: unknown; reasons?: unknown; reason?: unknown }): Outcome {
  if (result.ok) return 'accepted';
  const reasons = result.errors ?? result.reasons ?? (typeof result.reason === 'string' ? [result.reason] : undefined);
  return isReasons(reasons) ? 'refused' : 'crashed';
}

async function link(prefix: string, input: FuzzInput): Promise<string> {
  return input.raw ? input.text : `${prefix}${toBase64Url(await deflate(new TextEncoder().encode(input.text)))}`;
}

function playedProgress(): unknown {
  const clock = new FakeClock();
  const catalog = loadLevels(levelFiles.get('index.json') ?? '', (name) => levelFiles.get(name));
  const engine = new QuestEngine({ catalog, progress: newProgress(clock), clock, session: 'fuzz' });
  engine.openLevel('01-introduction');
  engine.askHint('orbit');
  return JSON.parse(exportProgress(engine.progress));
}

export async function fuzzTargets(): Promise<FuzzTarget[]> {
  const assignment: Assignment = {
    version: 1,
    title: 'Lesson 1',
    levels: ['01-introduction', '02-rays-from-the-camera'],
    requiredTasks: { '01-introduction': ['orbit'] },
    otherLevels: 'hidden',
    locale: 'en',
    askParticipantCode: true,
    survey: 'default',
  };
  // The index is fuzzed over two small levels: reading the game's twenty on every case would take minutes.
  const smallLevels = new Map(['first', 'second'].map((id) => [levelFileName(id), JSON.stringify(levelWithId(id))]));
  const smallIndex = { version: 1, chapters: [{ id: 'test', title: { en: 'Test', nl: 'Test' }, levels: ['first', 'second'] }] };
  return [
    { name: 'scene', sample: defaultScene(), run: async ({ text }) => judged(parseSceneJson(text)) },
    { name: 'level', sample: firstLevel, run: async ({ text }) => judged(parseLevelJson(text)) },
    {
      name: 'level index',
      sample: smallIndex,
      run: async ({ text }) => {
        const catalog = loadLevels(text, (name) => smallLevels.get(name));
        return catalog.errors.length === 0 ? 'accepted' : isReasons(catalog.errors) ? 'refused' : 'crashed';
      },
    },
    { name: 'assignment link', sample: assignment, run: async (input) => judged(await decodeAssignment(await link(`${LINK_PREFIX}${LINK_VERSION}.`, input))) },
    { name: 'scene link', sample: defaultScene(), run: async (input) => judged(await decodeSceneLink(await link(SCENE_LINK_PREFIX, input))) },
    { name: 'progress', sample: playedProgress(), run: async ({ text }) => judged(parseProgressJson(text)) },
    {
      name: 'survey',
      sample: defaultSurvey,
      run: async ({ text }) => {
        const json = readJson(text);
        return json.ok ? judged(parseSurvey(json.value)) : 'refused';
      },
    },
    { name: 'dashboard file', sample: simulatedExport(0), run: async ({ text, raw }) => judged(readExportFile(raw ? 'learner.csv' : 'learner.json', text)) },
  ];
}

// ─── Inputs ──────────────────────────────────────────────────────────────────────────────

type Json = unknown;

/** Every place in a JSON value, as a path of keys. */
function places(value: Json, path: (string | number)[] = [], found: (string | number)[][] = []): (string | number)[][] {
  found.push(path);
  if (Array.isArray(value)) value.forEach((item, index) => places(item, [...path, index], found));
  else if (value !== null && typeof value === 'object') for (const [key, item] of Object.entries(value)) places(item, [...path, key], found);
  return found;
}

type Change = { kind: 'replace'; with: Json } | { kind: 'remove' } | { kind: 'repeat'; times: number } | { kind: 'long-key'; length: number };

/** `sample` with one place changed (a deep copy; the sample is left alone). */
function changed(sample: Json, pick: number, change: Change): Json {
  const root = structuredClone(sample);
  const all = places(root);
  const path = all[pick % all.length];
  if (path.length === 0) return change.kind === 'replace' ? change.with : root;
  const parent = path.slice(0, -1).reduce<Json>((node, key) => (node as Record<string | number, Json>)[key], root) as Record<string | number, Json>;
  const key = path[path.length - 1];
  switch (change.kind) {
    case 'replace':
      parent[key] = change.with;
      break;
    case 'remove':
      if (Array.isArray(parent)) parent.splice(key as number, 1);
      else delete parent[key];
      break;
    case 'repeat':
      // A list of many copies: the survey of 2,000 duplicated questions once took 3.9 s.
      if (Array.isArray(parent)) parent.push(...Array.from({ length: change.times }, () => structuredClone(parent[key as number])));
      else parent[key] = Array.from({ length: change.times }, () => parent[key]);
      break;
    case 'long-key':
      parent[`${String(key)}${'k'.repeat(change.length)}`] = parent[key];
      break;
  }
  return root;
}

const changeArbitrary: fc.Arbitrary<Change> = fc.oneof(
  { weight: 4, arbitrary: fc.anything({ maxDepth: 3 }).map((value): Change => ({ kind: 'replace', with: value })) },
  { weight: 2, arbitrary: fc.constant<Change>({ kind: 'remove' }) },
  { weight: 1, arbitrary: fc.integer({ min: 2, max: 3000 }).map((times): Change => ({ kind: 'repeat', times })) },
  { weight: 1, arbitrary: fc.integer({ min: 60, max: 100_000 }).map((length): Change => ({ kind: 'long-key', length })) },
);

/** The cases for a target: mostly variations of its sample, some cut-short files, random JSON and random text. */
export function inputsFor(target: FuzzTarget): fc.Arbitrary<FuzzInput> {
  const sampleText = JSON.stringify(target.sample);
  const text = (value: string): FuzzInput => ({ text: value, raw: false });
  return fc.oneof(
    { weight: 1, arbitrary: fc.constant(text(sampleText)) },
    {
      weight: 10,
      arbitrary: fc.tuple(fc.nat(), changeArbitrary).map(([pick, change]) => text(JSON.stringify(changed(target.sample, pick, change)) ?? 'null')),
    },
    { weight: 2, arbitrary: fc.nat({ max: sampleText.length }).map((cut) => text(sampleText.slice(0, cut))) },
    { weight: 2, arbitrary: fc.json({ maxDepth: 4 }).map(text) },
    { weight: 1, arbitrary: fc.string({ maxLength: 200 }).map((value): FuzzInput => ({ text: value, raw: true })) },
    { weight: 1, arbitrary: fc.string({ unit: 'binary', maxLength: 200 }).map(text) },
  );
}

// ─── Running ─────────────────────────────────────────────────────────────────────────────

export interface FuzzTally {
  name: string;
  cases: number;
  refused: number;
  accepted: number;
  crashed: number;
  hangs: number;
  slowestMs: number;
  /** The first crash or hang, to reproduce it. */
  firstProblem: string | null;
}

/** Runs `cases` generated inputs through the target (seeded: the same cases every run). */
export async function fuzz(target: FuzzTarget, cases: number, seed = 15): Promise<FuzzTally> {
  const tally: FuzzTally = { name: target.name, cases: 0, refused: 0, accepted: 0, crashed: 0, hangs: 0, slowestMs: 0, firstProblem: null };
  const note = (problem: string, input: FuzzInput) => (tally.firstProblem ??= `${problem} on ${JSON.stringify(input).slice(0, 300)}`);
  await fc.assert(
    fc.asyncProperty(inputsFor(target), async (input) => {
      tally.cases++;
      const start = performance.now();
      let outcome: Outcome;
      try {
        outcome = await target.run(input);
      } catch (error) {
        outcome = 'crashed';
        note(`threw ${error instanceof Error ? error.message : String(error)}`, input);
      }
      const ms = performance.now() - start;
      tally.slowestMs = Math.max(tally.slowestMs, ms);
      if (ms > HANG_MS) {
        tally.hangs++;
        note(`took ${Math.round(ms)} ms`, input);
      }
      if (outcome === 'crashed') note('a malformed result', input);
      tally[outcome]++;
    }),
    { numRuns: cases, seed },
  );
  return tally;
}
