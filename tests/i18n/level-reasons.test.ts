// The reasons a broken level file, the level index, saved progress or an assignment link is
// refused for, as the learner reads them in Dutch: each produced by the real loader from a
// real level with one mistake. The last test runs every message those loaders can give
// (found in their source) through the Dutch text and fails on one still in English.
import { readFileSync } from 'node:fs';
import ts from 'typescript';
import { describe, expect, it } from 'vitest';
import { decodeAssignment, encodeAssignment } from '../../src/classroom/assignment-link.ts';
import { readExportFile } from '../../src/classroom/dashboard-read-file.ts';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { issueText } from '../../src/i18n/issue-text.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { parseProgress } from '../../src/quest/progress-store.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { issueLine, type Issue } from '../../src/util/issue.ts';
import { simulatedExport } from '../support/class-exports.ts';
import { inDutch } from '../support/page-locale.ts';

const levelText = (name: string) => readFileSync(new URL(`../../levels/${name}`, import.meta.url), 'utf8');

// Level 3 has every kind of task (info, quiz, pixel picks, state goals, an `all`, a `where`), a guide per task and a view.
const SHADING = '03-shading.level.json';
const shading = JSON.parse(levelText(SHADING)) as Level;

/** The parts of a level file the mistakes below touch, loosely typed: they write what a wrong file may hold. */
interface Level {
  id: string;
  chapter: string;
  ui: { panels: string[]; controls?: Record<string, unknown>; hidden?: Record<string, unknown> };
  badges?: unknown[];
  scene: { camera: Record<string, unknown>; settings: Record<string, unknown>; objects: Record<string, unknown>[] };
  tasks: { id: string; mandatory?: boolean; goal: unknown; guide?: string; hints?: unknown[]; solution?: unknown[]; view?: Record<string, unknown> }[];
}

/** The reasons the real level loader gives level 3 with `change` made to a copy, through levels/index.json. */
function reasonsWith(change: (level: Level) => void): Issue[] {
  const level = structuredClone(shading);
  change(level);
  const catalog = loadLevels(levelText('index.json'), (fileName) => (fileName === SHADING ? JSON.stringify(level) : levelText(fileName)));
  const entry = catalog.chapters.flatMap((chapter) => chapter.entries).find((candidate) => candidate.id === shading.id);
  if (!entry || entry.ok) throw new Error('the broken level was accepted');
  return entry.errors;
}

type Goal = Record<string, unknown>;
const goalOf = (level: Level, task: number) => level.tasks[task]!.goal as Goal;

/** One mistake per level rule, goal check, path check and view check (level 3's tasks: 0 info, 1–3 pixel picks, 4 a state goal, 7 a quiz, 9 an `all`, 10 a `where`). */
const LEVEL_MISTAKES: Record<string, (level: Level) => void> = {
  'a task id twice': (level) => (level.tasks[1]!.id = level.tasks[0]!.id),
  'too few mandatory tasks': (level) => level.tasks.forEach((task) => (task.mandatory = false)),
  'no solution': (level) => delete level.tasks[4]!.solution,
  'no hints': (level) => (level.tasks[4]!.hints = []),
  'a view as a step': (level) => level.tasks[4]!.solution!.push({ type: 'view.applied', view: {} }),
  'a quiz with a solution': (level) => (level.tasks[7]!.solution = [{ type: 'render.started' }]),
  'an info step with a solution': (level) => (level.tasks[0]!.solution = [{ type: 'render.started' }]),
  'an optional info step': (level) => (level.tasks[0]!.mandatory = false),
  'a guide to a hidden panel': (level) => (level.tasks[4]!.guide = 'light.intensity'),
  'a guide to a hidden control': (level) => (level.tasks[4]!.guide = 'object.color'),
  'a guide to a missing object': (level) => (level.tasks[4]!.guide = 'view.item:teapot'),
  'a guide to a pixel off the screen': (level) => (level.tasks[4]!.guide = 'screen.pixel:9,9'),
  'a guide to another pixel': (level) => (level.tasks[1]!.guide = 'screen.pixel:0,0'),
  'no pixel preview': (level) => (level.ui.panels = level.ui.panels.filter((panel) => panel !== 'screen-preview')),
  'a badge for a missing task': (level) => (level.badges = [{ id: 'all-rays', title: 'All rays', text: 'Well done', tasks: ['no-such-task'] }]),
  'a guide that is no control': (level) => (level.tasks[4]!.guide = 'the ambient slider'),
  'controls of a panel not shown': (level) => (level.ui.controls = { ...level.ui.controls, light: ['intensity'] }),
  'a reason to hide a panel it shows': (level) => (level.ui.hidden = { debugger: { en: 'Not yet.', nl: 'Nog niet.' } }),
  'a path that starts wrong': (level) => (goalOf(level, 4).state = '.scene'),
  'a path that cannot be read': (level) => (goalOf(level, 4).state = 'scene..settings'),
  'a quiz answer past its choices': (level) => ((goalOf(level, 7).quiz as Goal).answer = 5),
  'a goal on the view': (level) => (level.tasks[1]!.goal = { event: 'view.applied' }),
  'with on an action without fields': (level) => (level.tasks[1]!.goal = { event: 'render.started', with: { ms: 3 } }),
  'with on a field the action lacks': (level) => (level.tasks[1]!.goal = { event: 'pixel.selected', with: { column: 2 } }),
  'an ordering of a text': (level) => (goalOf(level, 4).value = 'low'),
  'a goal that is a number': (level) => (level.tasks[4]!.goal = 3),
  'an info goal inside all': (level) => (goalOf(level, 9).all as unknown[]).push({ info: true }),
  'a goal of no kind': (level) => (level.tasks[4]!.goal = { expect: 'red' }),
  'a goal of two kinds': (level) => (level.tasks[4]!.goal = { event: 'render.started', state: 'scene.settings.shadows', op: '==', value: true }),
  'a condition mixing comparisons and fields': (level) => (goalOf(level, 10).where = { 'scene.objects[id=ball].material.specular': { '>=': 0.5, red: 1 } }),
  'a path into a list by name': (level) => (goalOf(level, 4).state = 'scene.objects.material'),
  'a misspelt field': (level) => (goalOf(level, 4).state = 'scene.setings.shadows'),
  'a misspelt first field': (level) => (goalOf(level, 4).state = 'sceen.settings'),
  'a path into a true or false': (level) => (goalOf(level, 4).state = 'scene.settings.shadows.on'),
  'a path into a number by position': (level) => (goalOf(level, 4).state = 'scene.camera[0]'),
  'a view framing a missing object': (level) => (level.tasks[2]!.view!.frame = ['teapot']),
  'a view choosing a pixel off the screen': (level) => (level.tasks[2]!.view!.pixel = [9, 9]),
  'a view framing rays without a pixel': (level) => (level.tasks[2]!.view!.frame = ['pixel-rays']),
  'a view from nowhere': (level) => (level.tasks[2]!.view!.from = [0, 0, 0]),
  'evidence naming a ray by no path': (level) => Object.assign(level.tasks[2]!, { evidence: { rays: { pixel: [3, 2], paths: ['shadow'] } } }),
  'evidence of a missing object and pixel': (level) =>
    Object.assign(level.tasks[2]!, { evidence: { objects: ['teapot'], rays: { pixel: [9, 9], paths: ['primary'] } } }),
  'a view framing and through the camera': (level) => (level.tasks[2]!.view!.throughCamera = true),
  'a view from a side without a frame': (level) => delete level.tasks[2]!.view!.frame,
  'ray options that are a number': (level) => (level.tasks[2]!.view!.rays = 3),
  'ray options with two mistakes': (level) => (level.tasks[2]!.view!.rays = { glow: true, hideNoHit: 'yes' }),
  'scene changes that are a number': (level) => level.tasks[4]!.solution!.push({ type: 'material.changed', id: 'ball', changes: 3 }),
  'a camera looking at itself': (level) => (level.scene.camera.target = level.scene.camera.position),
  'a mesh without its model': (level) => (level.scene.objects[0]!.shape = 'mesh'),
  'a model on a sphere': (level) => (level.scene.objects[1]!.mesh = 'teapot'),
  'an object id twice': (level) => (level.scene.objects[1]!.id = level.scene.objects[0]!.id),
  'an object id three times': (level) => level.scene.objects.push({ ...level.scene.objects[0]! }, { ...level.scene.objects[0]! }),
  'too many primary rays': (level) => {
    Object.assign(level.scene.settings, { supersampling: 8, timeSamples: 8 });
    level.scene.camera.lensSamples = 8;
  },
  'an id with capitals': (level) => (level.id = 'Shading'),
  'a figure the app does not ship': (level) => Object.assign(level.tasks[0]!, { figure: { src: 'torch.svg', alt: 'A torch.' } }),
};

/** The reasons of the level index, through the same loader (levels/index.json with one mistake). */
function indexReasons(): Issue[] {
  const index = JSON.parse(levelText('index.json')) as {
    chapters: { id: string; levels: string[] }[];
    ideas: Record<string, unknown>;
    presets: { levels: string[] }[];
  };
  const [first, second] = index.chapters;
  // A teacher's idea too long for its line; then an idea for a level no chapter lists.
  const longIdea = structuredClone(index);
  longIdea.ideas[first!.levels[0]!] = { en: 'x'.repeat(101) };
  const tooLong = loadLevels(JSON.stringify(longIdea), levelText);
  index.ideas['retired-level'] = 'A level that was removed';
  first!.levels.push('no-such-level', first!.levels[0]!);
  const twice = loadLevels(JSON.stringify(index), levelText);
  const wrongPlace = structuredClone(shading);
  wrongPlace.id = 'shading-copy';
  wrongPlace.chapter = second!.id === shading.chapter ? first!.id : second!.id;
  const moved = loadLevels(levelText('index.json'), (fileName) => (fileName === SHADING ? JSON.stringify(wrongPlace) : levelText(fileName)));
  const missing = loadLevels(levelText('index.json'), (fileName) => (fileName === SHADING ? undefined : levelText(fileName)));
  const brokenEntries = (catalog: ReturnType<typeof loadLevels>) =>
    catalog.chapters.flatMap((chapter) => chapter.entries.flatMap((entry) => (entry.ok ? [] : entry.errors)));
  return [...twice.errors, ...tooLong.errors, ...brokenEntries(moved), ...brokenEntries(missing)];
}

const clock = { monotonicMs: () => 0, wallMs: () => Date.parse('2026-12-01T10:00:00Z') };

/** Saved progress that is not ours, of another version, and with its events out of order. */
function progressReasons(): Issue[] {
  const progress = newProgress(clock) as unknown as Record<string, unknown> & { log: { events: unknown[] } };
  const event = (t: number, id: string) => ({ t, id, type: 'tab.hidden' });
  const outOfOrder = { ...progress, log: { ...progress.log, events: [event(20, 'tab.1'), event(10, 'tab.2')] } };
  const badId = { ...progress, log: { ...progress.log, events: [event(20, 'Tab 1')] } };
  return [{ kind: 'notes' }, { ...progress, version: 7 }, outOfOrder, badId].flatMap((input) => {
    const parsed = parseProgress(input);
    if (parsed.ok) throw new Error('the broken progress was accepted');
    return parsed.errors;
  });
}

/** An assignment link that lists a level twice, requires tasks of a level it does not list, and has a wrong class code and home page. */
async function assignmentReasons(): Promise<Issue[]> {
  const assignment = {
    version: 1,
    title: 'Lesson 2',
    levels: ['shading', 'shading'],
    requiredTasks: { shadows: ['shadow-ray'] },
    otherLevels: 'hidden',
    locale: 'nl',
    askParticipantCode: false,
    survey: null,
    classCode: '3B and 3C',
    xapiHomePage: 'ftp://school.example',
  } satisfies Assignment;
  const decoded = await decodeAssignment(await encodeAssignment(assignment));
  if (decoded.ok) throw new Error('the broken assignment was accepted');
  return decoded.reasons;
}

const reasonsOf = (name: string) => reasonsWith(LEVEL_MISTAKES[name]!);

describe('a broken level in Dutch', () => {
  inDutch();

  it('says the level rules in Dutch', () => {
    expect(reasonsOf('no solution').map(issueText)).toEqual([
      'tasks[4].solution: is verplicht: de handelingen waarmee deze taak af is ("Laat zien" voert ze uit)',
    ]);
    expect(reasonsOf('an optional info step').map(issueText)).toEqual(['tasks[0].mandatory: een uitlegstap lees je onderweg: die moet verplicht zijn']);
    expect(reasonsOf('a guide to a hidden panel').map(issueText)).toEqual([
      'tasks[4].guide: "light.intensity" staat in het paneel light, maar dit level toont dat paneel niet (ui.panels)',
    ]);
    expect(reasonsOf('a guide to a missing object').map(issueText)).toEqual([
      'tasks[4].guide: de scène van dit level heeft geen object of lamp "teapot" (wel: floor, ball, lamp)',
    ]);
    expect(reasonsOf('a guide to a pixel off the screen').map(issueText)).toEqual([
      'tasks[4].guide: "9,9" moet "kolom,rij" zijn, binnen het scherm van 6×4, geteld vanaf 0',
    ]);
    expect(reasonsOf('a badge for a missing task').map(issueText)).toEqual(['badges[0].tasks[0]: dit level heeft geen taak "no-such-task"']);
    // Said by their codes (local-reason.ts), not read back out of English.
    expect(
      ['no solution', 'an optional info step', 'a guide to a hidden panel', 'a guide to a pixel off the screen', 'a badge for a missing task'].flatMap((name) =>
        reasonsOf(name).map((issue) => issue.reason.code),
      ),
    ).toEqual(['solutionRequired', 'infoNotMandatory', 'panelNotShown', 'pixelOffScreen', 'noSuchTask']);
  });

  it('says the goal, condition and path checks in Dutch', () => {
    expect(reasonsOf('a goal of two kinds').map(issueText)).toEqual([
      'tasks[4].goal: mag maar één van de velden event, state, all, any, quiz, estimate, picture, challenge, code, info hebben, maar heeft event en state',
    ]);
    expect(reasonsOf('an ordering of a text').map(issueText)).toEqual(['tasks[4].goal.value: "<=" vergelijkt getallen, maar krijgt "low"']);
    expect(reasonsOf('a misspelt field').map(issueText)).toEqual([
      expect.stringMatching(/^tasks\[4\]\.goal\.state: er is geen veld "setings" in scene \(wel: .*settings.*\)$/),
    ]);
    expect(reasonsOf('a path into a true or false').map(issueText)).toEqual([
      'tasks[4].goal.state: scene.settings.shadows is true of false: daarin zit geen veld "on"',
    ]);
    expect(reasonsOf('with on a field the action lacks').map(issueText)).toEqual([
      'tasks[1].goal.with.column: een actie "pixel.selected" heeft alleen deze velden: pixel',
    ]);
  });

  it('says the view and option checks in Dutch, each of several on a line of its own', () => {
    expect(reasonsOf('a view framing rays without a pixel').map(issueText)).toEqual([
      'tasks[2].view.frame: "pixel-rays" kan alleen als de weergave ook een pixel kiest ("pixel": [kolom, rij])',
    ]);
    expect(reasonsOf('a view from nowhere').map(issueText)).toEqual(['tasks[2].view.from: moet een richting zijn, niet [0, 0, 0]']);
    expect(reasonsOf('ray options with two mistakes').map(issueText)).toEqual([
      expect.stringMatching(/^tasks\[2\]\.view\.rays: onbekend veld "glow" \(bekend zijn: showRays, .*\)$/),
      'tasks[2].view.rays: hideNoHit moet true of false zijn, maar is "yes"',
    ]);
  });

  it("says the level index's reasons in Dutch", () => {
    const dutch = indexReasons().map(issueText);
    expect(dutch).toContain(
      `chapters[0].levels[${JSON.parse(levelText('index.json')).chapters[0].levels.length + 1}]: "${JSON.parse(levelText('index.json')).chapters[0].levels[0]}" komt meer dan één keer voor`,
    );
    expect(dutch).toContain(`id: moet "${shading.id}" zijn, de naam waaronder index.json dit bestand noemt, maar is "shading-copy"`);
    expect(dutch).toContain('(het geheel): het bestand levels/03-shading.level.json bestaat niet');
    expect(dutch).toContain('ideas.retired-level: "retired-level" staat in geen enkel hoofdstuk');
    expect(dutch).toContainEqual(expect.stringMatching(/^ideas\.\S+\.en: .*100/));
  });

  it('says the reasons of saved progress and of an assignment link in Dutch', async () => {
    expect(progressReasons().map(issueText)).toEqual([
      'kind: moet "ray-tracer-quest-progress" zijn in een voortgangsbestand, maar is "kind" "notes"',
      'version: deze app leest voortgang van versie 1, maar de versie is 7',
      'log.events[1].t: mag niet eerder zijn dan de gebeurtenis ervoor',
      'log.events[0].id: ongeldige tekst: moet passen bij het patroon /^[a-z0-9]{1,16}\\.\\d{1,9}$/',
    ]);
    expect((await assignmentReasons()).map(issueText)).toEqual([
      'classCode: een klascode heeft 1 tot 32 letters, cijfers, - of _',
      'xapiHomePage: moet een webadres zijn dat begint met http:// of https://',
      'levels[1]: "shading" staat er meer dan één keer in',
      'requiredTasks.shadows: "shadows" hoort niet bij de levels van de lesopdracht',
    ]);
  });
});

describe('a file the dashboard skips, in Dutch', () => {
  inDutch();

  /** Why `text` is skipped, as the dashboard page shows it. */
  const skipped = (name: string, text: string) => {
    const read = readExportFile(name, text);
    if (read.ok) throw new Error('the damaged export was read');
    return read.detail === undefined ? read.reason : `${read.reason}: ${issueText(read.detail)}`;
  };
  const good = simulatedExport(0);

  it('says the damage of a JSON export, an event log and a CSV export in Dutch', () => {
    expect(skipped('p.json', JSON.stringify(good).slice(0, 40))).toMatch(
      /^het bestand is beschadigd: \(het geheel\): geen geldige JSON op regel 1, kolom 41: verwacht werd .*, maar er staat het einde van de tekst$/,
    );
    expect(skipped('p.json', JSON.stringify({ ...good, participant: 42 }))).toBe('beschadigde export: participant: moet een tekst zijn, maar is 42');
    const backwards = good.events.events.map((event, index) => (index === 4 ? { ...event, t: 0 } : event));
    expect(skipped('p.json', JSON.stringify({ ...good, events: { ...good.events, events: backwards } }))).toBe(
      'beschadigd logboek: events.events[4].t: mag niet eerder zijn dan de gebeurtenis ervoor',
    );
    const header = 'participant,level,task,started_at,duration_ms,active_ms\n';
    expect(skipped('a.csv', `${header}P1,L1,a,2026-03-09T09:00:00Z,ten,5\n`)).toBe(
      'beschadigde CSV: regel 2: duration_ms moet een getal van minstens 0 zijn, maar is "ten"',
    );
    expect(skipped('a.csv', `${header}"P1,L1,a,2026-03-09T09:00:00Z,10,5\n`)).toBe(
      'beschadigde CSV: een veld tussen aanhalingstekens dat op regel 2 begint, wordt nooit gesloten',
    );
  });
});

/** Where the loaders above word their reasons. */
const REASON_SOURCES = [
  'src/quest/level-rules.ts',
  'src/quest/level-schema.ts',
  'src/quest/goal.ts',
  'src/quest/condition.ts',
  'src/quest/state-path.ts',
  'src/quest/declared-view-schema.ts',
  'src/quest/option-changes.ts',
  'src/quest/lab-action-schema.ts',
  'src/quest/level-index.ts',
  'src/quest/kebab-id.ts',
  'src/quest/progress-store.ts',
  'src/quest/event-log.ts',
  'src/scene/scene-rules.ts',
  'src/classroom/assignment-schema.ts',
];

/**
 * The fixed words of every text in `path` that reads as English words (two words in a row):
 * a template's pieces between its `${…}`, a string whole. Descriptions for the file's authors
 * (`.describe(…)`) are no reasons.
 */
function wordedTexts(path: string): string[][] {
  const source = ts.createSourceFile(path, readFileSync(new URL(`../../${path}`, import.meta.url), 'utf8'), ts.ScriptTarget.Latest, true);
  const found: string[][] = [];
  const worded = (text: string) => /[a-z]{2,} [a-z]{2,}/i.test(text);
  const visit = (node: ts.Node): void => {
    const call = node.parent && ts.isCallExpression(node.parent) ? node.parent : undefined;
    const described = call && ts.isPropertyAccessExpression(call.expression) && call.expression.name.text === 'describe';
    if (!described) {
      if (ts.isStringLiteral(node) || ts.isNoSubstitutionTemplateLiteral(node)) {
        if (worded(node.text)) found.push([node.text]);
      } else if (ts.isTemplateExpression(node)) {
        const pieces = [node.head.text, ...node.templateSpans.map((span) => span.literal.text)];
        if (pieces.some(worded)) found.push(pieces.filter((piece) => piece.trim() !== ''));
      }
    }
    ts.forEachChild(node, visit);
  };
  visit(source);
  return found;
}

type Problem = Issue;
const lineOf = (problem: Problem) => issueLine(problem);

/** Every reason the mistakes above produce, once each (by its English line). */
async function everyReason(): Promise<Problem[]> {
  const all = [
    ...Object.values(LEVEL_MISTAKES).flatMap((mistake) => reasonsWith(mistake)),
    ...indexReasons(),
    ...progressReasons(),
    ...(await assignmentReasons()),
  ];
  return [...new Map(all.map((problem) => [lineOf(problem), problem])).values()];
}

describe('every reason of the level, progress and assignment loaders in Dutch', () => {
  inDutch();

  it('is produced above, and no reason comes out still in English', async () => {
    const problems = await everyReason();
    const english = problems.map(lineOf);
    // Every worded text of the sources is in some reason produced: a new message without a mistake that shows it fails here.
    for (const path of REASON_SOURCES) {
      for (const pieces of wordedTexts(path)) {
        expect(
          english.some((line) => pieces.every((piece) => line.includes(piece))),
          `${path}: ${pieces.join('…')}`,
        ).toBe(true);
      }
    }
    // Reasons that are field names or literals, the same in both languages: none so far.
    const sameInBothLanguages: string[] = [];
    for (const problem of problems) {
      const line = lineOf(problem);
      const dutch = issueText(problem);
      if (sameInBothLanguages.includes(line)) continue;
      expect(dutch, line).not.toBe(line);
      expect(dutch.slice(dutch.indexOf(': ') + 2), line).not.toMatch(
        /\b(must|got|unknown|is required|is used|needs|cannot|not both|has no|there is no|is listed|this app|the event)\b/,
      );
    }
  });
});

describe('every reason back in English', () => {
  it("is the loader's own line again, though the Dutch sayings are loaded", async () => {
    const problems = await everyReason();
    expect(problems.map(issueText)).toEqual(problems.map(lineOf));
  });
});
