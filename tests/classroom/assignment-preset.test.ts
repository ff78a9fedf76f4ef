import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { mandatoryTasks, withPreset } from '../../src/classroom/assignment-preset.ts';
import { loadLevelGuide, loadLevels, playableLevels } from '../../src/quest/level-index.ts';

const levelsFolder = new URL('../../levels/', import.meta.url);
const indexText = readFileSync(new URL('index.json', levelsFolder), 'utf8');
const levels = playableLevels(loadLevels(indexText, (name) => readFileSync(new URL(name, levelsFolder), 'utf8')));
const [corePreset] = loadLevelGuide(indexText).presets;

const assignment: Assignment = {
  version: 1,
  title: 'Lesson',
  levels: ['06-refraction', '01-introduction'],
  requiredTasks: { '06-refraction': ['diamond'], '01-introduction': ['orbit', 'pan'] },
  otherLevels: 'hidden',
  locale: 'nl',
  askParticipantCode: true,
  survey: 'default',
  classCode: '3B',
};

describe('a preset on the teacher page', () => {
  it("selects exactly the short path's levels, in its order, each with its own mandatory tasks", () => {
    const chosen = withPreset(assignment, corePreset!, levels);
    expect(chosen.levels).toEqual([
      '01-introduction',
      '02-rays-from-the-camera',
      '03-shading',
      '04-shadows',
      '05-reflections',
      '10-area-lights',
      '11-anti-aliasing',
      '14-finding-your-way',
    ]);
    expect(Object.keys(chosen.requiredTasks)).toEqual(chosen.levels);
    for (const id of chosen.levels) {
      const level = levels.find((candidate) => candidate.id === id)!;
      expect(chosen.requiredTasks[id], id).toEqual(level.tasks.filter((task) => task.mandatory).map((task) => task.id));
      expect(chosen.requiredTasks[id]!.length, id).toBeGreaterThan(0);
    }
  });

  it("keeps the teacher's other choices, and leaves out a level this game cannot play", () => {
    const chosen = withPreset(assignment, { id: 'mixed', title: 'Mixed', levels: ['04-shadows', '99-not-made-yet', '01-introduction'] }, levels);
    expect(chosen).toEqual({
      ...assignment,
      levels: ['04-shadows', '01-introduction'],
      requiredTasks: { '04-shadows': mandatoryTasks(levels.find((level) => level.id === '04-shadows')!), '01-introduction': mandatoryTasks(levels[0]!) },
    });
  });
});
