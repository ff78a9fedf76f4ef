import { loadLevels, levelFileName, type LevelCatalog } from '../../src/quest/level-index.ts';
import type { QuestClock } from '../../src/quest/event-log.ts';
import type { Prediction } from '../../src/quest/goal-check.ts';
import type { PredictionGoal } from '../../src/quest/goal.ts';

/** Test doubles and small levels shared by the quest tests. */

/** A clock the test moves by hand; both readings advance together unless told otherwise. */
export class FakeClock implements QuestClock {
  monotonic = 1_000;
  wall = Date.parse('2025-03-01T09:00:00.000Z');

  monotonicMs(): number {
    return this.monotonic;
  }

  wallMs(): number {
    return this.wall;
  }

  advance(ms: number): void {
    this.monotonic += ms;
    this.wall += ms;
  }
}

type Json = Record<string, unknown>;

/**
 * A small valid level (as a level file's JSON): three mandatory tasks of three kinds and
 * two optional ones. `change` edits a deep copy, so each test says only what it varies.
 */
export function levelFile(change: (level: Json & { tasks: Json[] }) => void = () => {}): Json {
  const level = {
    version: 1,
    id: 'test-level',
    chapter: 'test',
    title: 'Test level',
    intro: { text: 'What this level is about.' },
    scene: {
      version: 1,
      camera: { pixels: [4, 3] },
      objects: [{ id: 'ball', position: [0, 0.5, 0], material: { color: [0.9, 0.1, 0.1] } }],
      lights: [{ id: 'lamp', position: [2, 4, 3] }],
    },
    ui: { panels: ['object', 'tracer', 'render'] },
    tasks: [
      {
        id: 'orbit',
        title: 'Look around',
        text: 'Orbit the view.',
        goal: { event: 'view.orbited' },
        hints: ['Drag in the view.', 'Or use the arrow buttons.'],
        guide: 'view.orbit-buttons',
        solution: [{ type: 'view.orbited' }],
      },
      {
        id: 'predict',
        title: 'Predict',
        text: 'How many primary rays?',
        goal: { quiz: { question: 'The screen is 4 × 3. How many primary rays?', choices: ['7', '12', '43'], answer: 1 } },
        hints: ['One per pixel.'],
      },
      {
        id: 'supersample',
        title: 'Smooth edges',
        text: 'Set supersampling to 2 or more.',
        goal: { state: 'scene.settings.supersampling', op: '>=', value: 2 },
        hints: ['Look in the ray tracer panel.'],
        guide: 'tracer.supersampling',
        solution: [{ type: 'settings.changed', changes: { supersampling: 2 } }],
      },
      {
        id: 'red-ball',
        title: 'Paint it red',
        text: 'Make the ball pure red.',
        mandatory: false,
        goal: { state: 'scene.objects[id=ball].material.color', op: '==', value: [1, 0, 0] },
        hints: ['Use the colour field.'],
        guide: 'object.color',
        solution: [{ type: 'material.changed', id: 'ball', changes: { color: [1, 0, 0] } }],
      },
      {
        id: 'zoom',
        title: 'Zoom',
        text: 'Zoom in.',
        mandatory: false,
        goal: { event: 'view.zoomed' },
        hints: ['Scroll.'],
        solution: [{ type: 'view.zoomed' }],
      },
    ],
  };
  const copy = structuredClone(level);
  change(copy);
  return copy;
}

/** A catalog of level files (objects are written as JSON; strings are used as they are, to test bad JSON). */
export function catalogOf(chapters: { id: string; levels: (Json | string)[] }[], extraFiles: Record<string, string> = {}): LevelCatalog {
  const files = new Map<string, string>(Object.entries(extraFiles));
  const index = {
    version: 1,
    chapters: chapters.map((chapter) => ({
      id: chapter.id,
      title: chapter.id,
      levels: chapter.levels.map((level) => {
        const text = typeof level === 'string' ? level : JSON.stringify(level);
        const id = typeof level === 'string' ? 'unparsable' : String(level.id);
        files.set(levelFileName(id), text);
        return id;
      }),
    })),
  };
  return loadLevels(JSON.stringify(index), (fileName) => files.get(fileName));
}

/** The test level under another id (and chapter), for catalogs of several levels. */
export function levelWithId(id: string, chapter = 'test'): Json {
  return levelFile((level) => {
    level.id = id;
    level.chapter = chapter;
  });
}

/** The prediction a learner who knows the answer gives. */
export function rightPrediction(goal: PredictionGoal): Prediction {
  switch (goal.kind) {
    case 'quiz':
      return { choice: goal.quiz.answer };
    case 'picture':
      return { choice: goal.picture.answer };
    case 'estimate':
      return { value: goal.estimate.answer };
    default: {
      const never: never = goal;
      return never;
    }
  }
}
