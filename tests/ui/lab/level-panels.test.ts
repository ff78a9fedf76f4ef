import { issueLine } from '../../../src/util/issue.ts';
import { describe, expect, it } from 'vitest';
import { parseLevel, type Level } from '../../../src/quest/level-schema.ts';
import { levelPanels } from '../../../src/ui/lab/level-panels.ts';
import { levelFile } from '../../support/quest-fixtures.ts';

/** The test level with `ui` as given. */
function levelWith(ui: Record<string, unknown>): Level {
  const result = parseLevel(levelFile((level) => (level.ui = ui)));
  if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
  return result.level;
}

describe('the ray legend over the 3D view', () => {
  it('shows in a level without the ray panel, or whose ray panel leaves the legend out', () => {
    expect(levelPanels(levelWith({ panels: ['object', 'tracer', 'render'] })).viewLegend).toBe(true);
    expect(levelPanels(levelWith({ panels: ['object', 'tracer', 'rays', 'render'], controls: { rays: ['hide-no-hit'] } })).viewLegend).toBe(true);
  });

  it('stays in the ray panel where that panel shows it, and in the free lab', () => {
    expect(levelPanels(levelWith({ panels: ['object', 'tracer', 'rays', 'render'] })).viewLegend).toBe(false);
    expect(levelPanels(levelWith({ panels: ['object', 'tracer', 'rays', 'render'], controls: { rays: ['legend', 'hide-no-hit'] } })).viewLegend).toBe(false);
    expect(levelPanels(undefined).viewLegend).toBe(false);
  });
});
