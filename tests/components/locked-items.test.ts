// A level's ui.movable in Chromium: level 32 lets the learner move only the ball. The 3D
// view and the scene list, on a real store with the level's own scene, keep the box where
// it is whatever the keys try, and say why; the ball still moves.
import { afterEach, describe, expect, it } from 'vitest';
import { page, userEvent } from 'vitest/browser';
import levelJson from '../../levels/32-match-the-shot.level.json';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { parseLevel, type Level } from '../../src/quest/level-schema.ts';
import '../../src/ui/lab/panels/rt-scene-list.ts';
import '../../src/ui/lab/rt-scene-view.ts';
import { mount, mountPanel, unmountAll } from './mount.ts';

afterEach(unmountAll);

function matchTheShot(): Level {
  const parsed = parseLevel(levelJson);
  if (!parsed.ok) throw new Error('level 32 does not parse');
  return parsed.level;
}

const REASON = 'Box is locked in this level: you can move only Ball.';

function positionOf(store: Store, id: string) {
  return store.state.scene.objects.find((object) => object.id === id)?.position;
}

describe('the 3D view with level 32 (only the ball can move)', () => {
  it('keeps the box where it is with arrows, Page Up and Delete, says why, and still moves the ball', async () => {
    const level = matchTheShot();
    expect(level.ui.movable).toEqual(['ball']);
    const store = new Store(initialState(level.scene));
    const view = await mount('rt-scene-view', { store, gizmoControls: ['translate'], movable: level.ui.movable });
    await expect.poll(() => view.labView, { timeout: 20_000 }).not.toBeNull();
    const boxAt = positionOf(store, 'box');

    store.dispatch({ type: 'selection.changed', selection: { kind: 'object', id: 'box' } });
    await expect.element(page.getByText(REASON)).toBeVisible();
    // No gizmo mode is offered for it.
    await expect.element(page.getByRole('button', { name: /^Move/ })).toHaveAttribute('aria-disabled', 'true');

    const canvas = page.getByRole('img', { name: /^3D view/ });
    (canvas.element() as HTMLElement).focus();
    for (const key of ['{ArrowRight}', '{ArrowUp}', '{PageUp}', '{Shift>}{ArrowLeft}{/Shift}', '{Delete}']) await userEvent.keyboard(key);
    expect(positionOf(store, 'box')).toEqual(boxAt);
    expect(store.state.selection).toEqual({ kind: 'object', id: 'box' });
    await expect.element(page.getByText(REASON)).toBeVisible();

    // T, R and S switch no gizmo mode on it: the box has no handles to switch.
    const gizmo = store.state.gizmo;
    for (const key of ['r', 's', 't']) {
      await userEvent.keyboard(key);
      expect(store.state.gizmo).toEqual(gizmo);
    }
    await expect.element(page.getByText(REASON)).toBeVisible();

    store.dispatch({ type: 'selection.changed', selection: { kind: 'object', id: 'ball' } });
    await expect.element(page.getByRole('button', { name: /^Move/ })).toHaveAttribute('aria-disabled', 'false');
    (canvas.element() as HTMLElement).focus();
    await userEvent.keyboard('{ArrowRight}');
    const [x, y, z] = positionOf(store, 'ball')!;
    // One 0.1 m step along a floor axis, from (−0.8, 0.5, 0).
    expect(Math.abs(x + 0.8) + Math.abs(z)).toBeCloseTo(0.1, 6);
    expect(y).toBe(0.5);
  });

  it('locks the camera too when the level does not name it', async () => {
    const level = matchTheShot();
    const store = new Store(initialState(level.scene));
    const view = await mount('rt-scene-view', { store, gizmoControls: ['translate'], movable: level.ui.movable });
    await expect.poll(() => view.labView, { timeout: 20_000 }).not.toBeNull();
    const camera = store.state.scene.camera;
    store.dispatch({ type: 'selection.changed', selection: { kind: 'camera' } });
    await expect.element(page.getByText("The ray tracer's camera is locked in this level: you can move only Ball.")).toBeVisible();
    (page.getByRole('img', { name: /^3D view/ }).element() as HTMLElement).focus();
    await userEvent.keyboard('{ArrowLeft}{PageDown}');
    expect(store.state.scene.camera).toEqual(camera);
  });
});

describe('the scene list with level 32', () => {
  it('marks the locked items, says why one is locked, and does not delete it', async () => {
    const level = matchTheShot();
    const store = new Store(initialState(level.scene));
    await mountPanel('rt-scene-list', store, { movable: level.ui.movable });
    await expect.element(page.getByRole('option', { name: /Box.*locked/ })).toBeVisible();
    await expect.element(page.getByRole('option', { name: /Ball/ })).not.toHaveAccessibleName(/locked/);
    await expect.element(page.getByText(REASON)).not.toBeInTheDocument();

    await page.getByRole('option', { name: /Box/ }).click();
    expect(store.state.selection).toEqual({ kind: 'object', id: 'box' });
    await expect.element(page.getByText(REASON)).toBeVisible();
    await expect.element(page.getByRole('option', { name: /Box/ })).toHaveAccessibleDescription(REASON);
    await expect.element(page.getByRole('button', { name: 'Delete' })).toBeDisabled();
    await userEvent.keyboard('{Delete}');
    expect(store.state.scene.objects.map((object) => object.id)).toContain('box');

    await page.getByRole('option', { name: /Ball/ }).click();
    await expect.element(page.getByText(REASON)).not.toBeInTheDocument();
    await expect.element(page.getByRole('button', { name: 'Delete' })).toBeEnabled();
  });
});
