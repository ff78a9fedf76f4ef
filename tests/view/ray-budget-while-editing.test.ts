import { describe, expect, it } from 'vitest';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import { EDIT_RAY_BUDGET, HEAVY_EDIT_RAYS } from '../../src/view/ray-budget.ts';
import { HELD_MS, RayBudgetWhileEditing, SETTLE_MS } from '../../src/view/ray-budget-while-editing.ts';
import { manualTimer } from '../support/manual-timer.ts';
import { syntheticScreen } from '../support/ray-fixtures.ts';

/** A RayBudgetWhileEditing on a manual clock, with the budgets it was applied with. */
function watched(screen: ScreenRays | null = null) {
  const timer = manualTimer();
  const applied: (number | null)[] = [];
  const budget: RayBudgetWhileEditing = new RayBudgetWhileEditing(
    () => applied.push(budget.budget),
    timer,
    () => screen,
  );
  return { timer, applied, budget };
}

describe('RayBudgetWhileEditing', () => {
  it('holds the rays to the budget from the first edit until the edits stop', () => {
    const { timer, applied, budget } = watched();
    expect(budget.budget).toBeNull();
    budget.edited(false);
    expect(applied).toEqual([EDIT_RAY_BUDGET]);
    // Arrow-key steps a few tenths of a second apart: one budget throughout.
    for (let step = 0; step < 10; step++) {
      timer.advance(SETTLE_MS - 1);
      budget.edited(false);
    }
    expect(applied).toEqual([EDIT_RAY_BUDGET]);
    timer.advance(SETTLE_MS);
    expect(applied).toEqual([EDIT_RAY_BUDGET, null]);
    expect(budget.budget).toBeNull();
  });

  it('keeps the budget while a dragged value is held still, until the drag is let go', () => {
    const { timer, applied, budget } = watched();
    budget.edited(true);
    timer.advance(SETTLE_MS * 3);
    expect(applied).toEqual([EDIT_RAY_BUDGET]);
    // Let go: the settled value, and all rays a moment later.
    budget.edited(false);
    timer.advance(SETTLE_MS);
    expect(applied).toEqual([EDIT_RAY_BUDGET, null]);
  });

  it('ends a drag let go where it was (its settled value changes nothing) as after any settled value', () => {
    const { timer, applied, budget } = watched();
    budget.letGo();
    expect(applied).toEqual([]);
    budget.edited(true);
    budget.letGo();
    timer.advance(SETTLE_MS);
    expect(applied).toEqual([EDIT_RAY_BUDGET, null]);
    // Anything else settled (a fact the lab logs) does not keep the budget after a settled edit.
    budget.edited(false);
    timer.advance(SETTLE_MS - 1);
    budget.letGo();
    timer.advance(1);
    expect(applied).toEqual([EDIT_RAY_BUDGET, null, EDIT_RAY_BUDGET, null]);
  });

  it('draws all rays again when a held drag never says it ended', () => {
    const { timer, applied, budget } = watched();
    budget.edited(true);
    timer.advance(HELD_MS);
    expect(applied).toEqual([EDIT_RAY_BUDGET, null]);
  });

  it('holds a screen heavier than the edit budget to fewer rays, from the first edit', () => {
    const { timer, applied, budget } = watched(syntheticScreen(3 * EDIT_RAY_BUDGET));
    expect(budget.editBudget).toBe(HEAVY_EDIT_RAYS);
    budget.edited(true);
    expect(applied).toEqual([HEAVY_EDIT_RAYS]);
    budget.edited(false);
    timer.advance(SETTLE_MS);
    expect(applied).toEqual([HEAVY_EDIT_RAYS, null]);
  });

  it('has a heavy screen traced from one sample per pixel while the edits last, a lighter one whole', () => {
    const heavy = watched(syntheticScreen(3 * EDIT_RAY_BUDGET)).budget;
    expect(heavy.oneSample).toBe(false);
    heavy.edited(true);
    expect(heavy.oneSample).toBe(true);
    heavy.letGo();
    const light = watched(syntheticScreen(EDIT_RAY_BUDGET - 5)).budget;
    light.edited(true);
    expect(light.oneSample).toBe(false);
  });

  it('leaves nothing pending once disposed', () => {
    const { timer, applied, budget } = watched();
    budget.edited(false);
    budget.dispose();
    timer.advance(HELD_MS);
    expect(applied).toEqual([EDIT_RAY_BUDGET]);
  });
});
