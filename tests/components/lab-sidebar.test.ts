// The lab's left column in Chromium, as a level declares it: the scene list offers Add and
// Delete only where the level shows the add-remove panel. Level 32 (a challenge that asks to
// move only the ball) must offer neither; the sandbox (level 17) offers both.
import { afterEach, describe, expect, it } from 'vitest';
import { page } from 'vitest/browser';
import { html, render, type LitElement } from 'lit';
import matchTheShotJson from '../../levels/32-match-the-shot.level.json';
import sandboxJson from '../../levels/17-sandbox.level.json';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { parseLevel } from '../../src/quest/level-schema.ts';
import { labSidebar } from '../../src/ui/lab/lab-sidebar.ts';
import { levelPanels } from '../../src/ui/lab/level-panels.ts';
import '../../src/ui/lab/panels/rt-scene-list.ts';

const host = document.createElement('div');
afterEach(() => {
  render(html``, host);
  host.remove();
});

async function sidebarOf(levelJson: unknown) {
  const parsed = parseLevel(levelJson);
  if (!parsed.ok) throw new Error('the level does not parse');
  const store = new Store(initialState(parsed.level.scene));
  document.body.append(host);
  render(html`${labSidebar(store.state, levelPanels(parsed.level))}`, host);
  const list = host.querySelector('rt-scene-list');
  if (!list) throw new Error('the level shows no scene list');
  Object.assign(list, { store });
  await (list as LitElement).updateComplete;
  return list;
}

describe('the scene list in a level’s sidebar', () => {
  it('offers no Add and no Delete where the level does not show add-remove', async () => {
    await sidebarOf(matchTheShotJson);
    await expect.element(page.getByRole('option', { name: /Ball/ })).toBeVisible();
    expect(page.getByRole('button', { name: /Add/ }).elements()).toHaveLength(0);
    expect(page.getByRole('button', { name: /^Delete/ }).elements()).toHaveLength(0);
  });

  it('offers Add in the sandbox, which shows add-remove', async () => {
    await sidebarOf(sandboxJson);
    await expect.element(page.getByRole('button', { name: /Add/ }).first()).toBeVisible();
  });
});
