import { describe, expect, it } from 'vitest';
import { EDIT_RAY_BUDGET } from '../../src/view/ray-budget.ts';
import { HELD_MS, RayBudgetWhileEditing, SETTLE_MS } from '../../src/view/ray-budget-while-editing.ts';
import { manualTimer } from '../support/manual-timer.ts';

/** A RayBudgetWhileEditing on a manual clock, with the budgets it was applied with. */
function watched() {
  const timer = manualTimer();
  const applied: (number | null)[] = [];
  const budget: RayBudgetWhileEditing = new RayBudgetWhileEditing(() => applied.push(budget.budget), timer);
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

  it('leaves nothing pending once disposed', () => {
    const { timer, applied, budget } = watched();
    budget.edited(false);
    budget.dispose();
    timer.advance(HELD_MS);
    expect(applied).toEqual([EDIT_RAY_BUDGET]);
  });
});
