// The panel controls in Chromium: each renders its value, answers keyboard and pointer,
// fires its declared events with the values asked for, clamps typed numbers out of range
// with a note, and stays controlled (shows its owner's value, not the one it asked for).
// Reached only through properties, events and what a user sees (roles and labels).
import { afterEach, describe, expect, it } from 'vitest';
import { page, userEvent } from 'vitest/browser';
import type { ValueDetail } from '../../src/ui/controls/control-element.ts';
import '../../src/ui/controls/rt-choice.ts';
import '../../src/ui/controls/rt-slider.ts';
import '../../src/ui/controls/rt-switch.ts';
import type { CheckedDetail } from '../../src/ui/controls/rt-switch.ts';
import '../../src/ui/controls/rt-vector-field.ts';
import { mount, record, unmountAll } from './mount.ts';

afterEach(unmountAll);

/** Acts as an owner (a panel) that takes every value its control asks for. */
function takeEveryChange<T>(element: HTMLElement & { value: T }): void {
  element.addEventListener('change', (event) => (element.value = (event as CustomEvent<ValueDetail<T>>).detail.value));
}

describe('rt-slider', () => {
  const setup = { name: 'pixels.columns', label: 'Pixel columns', tooltip: 'Columns of the screen', min: 1, max: 16, step: 1, inputMax: 64, whole: true };

  it('shows its value on the slider and in the field', async () => {
    const slider = await mount('rt-slider', { ...setup, value: 4 });
    const view = page.elementLocator(slider);
    await expect.element(view.getByRole('slider', { name: 'Pixel columns' })).toHaveValue('4');
    await expect.element(view.getByRole('textbox', { name: 'Pixel columns, typed value' })).toHaveValue('4');
  });

  it('steps with the arrow keys and jumps with End and Home, one change per key', async () => {
    const slider = await mount('rt-slider', { ...setup, value: 4 });
    const changes = record<ValueDetail<number>>(slider, 'change');
    takeEveryChange(slider);
    (page.elementLocator(slider).getByRole('slider').element() as HTMLElement).focus();
    await userEvent.keyboard('{ArrowRight}');
    await userEvent.keyboard('{End}');
    await userEvent.keyboard('{Home}');
    expect(changes.map((detail) => detail.value)).toEqual([5, 16, 1]);
    await expect.element(page.elementLocator(slider).getByRole('textbox')).toHaveValue('1');
  });

  it('takes the pointer: a press at the right end asks for the maximum', async () => {
    const slider = await mount('rt-slider', { ...setup, value: 4 });
    const changes = record<ValueDetail<number>>(slider, 'change');
    const range = page.elementLocator(slider).getByRole('slider');
    const box = range.element().getBoundingClientRect();
    await userEvent.click(range, { position: { x: box.width - 1, y: box.height / 2 } });
    expect(changes.at(-1)?.value).toBe(16);
  });

  it('clamps a typed value to the typed range and says so', async () => {
    const slider = await mount('rt-slider', { ...setup, value: 4 });
    const changes = record<ValueDetail<number>>(slider, 'change');
    const field = page.elementLocator(slider).getByRole('textbox');
    await userEvent.fill(field, '100');
    await userEvent.keyboard('{Enter}');
    expect(changes.map((detail) => detail.value)).toEqual([64]);
    await expect.element(page.elementLocator(slider).getByText('Clamped to 1–64')).toBeVisible();
    await userEvent.fill(field, '0');
    await userEvent.keyboard('{Enter}');
    expect(changes.map((detail) => detail.value)).toEqual([64, 1]);
  });

  it('rounds a typed fraction when whole, reads a decimal comma, and keeps its value for text that is no number', async () => {
    const slider = await mount('rt-slider', { ...setup, value: 4 });
    const changes = record<ValueDetail<number>>(slider, 'change');
    const field = page.elementLocator(slider).getByRole('textbox');
    await userEvent.fill(field, '2,6');
    await userEvent.keyboard('{Enter}');
    await userEvent.fill(field, 'many');
    await userEvent.keyboard('{Enter}');
    expect(changes.map((detail) => detail.value)).toEqual([3]);
    await expect.element(page.elementLocator(slider).getByText('Type a whole number between 1 and 64')).toBeVisible();
  });

  it("shows its owner's value when the owner refuses a change", async () => {
    const slider = await mount('rt-slider', { ...setup, value: 4 });
    const changes = record<ValueDetail<number>>(slider, 'change');
    (page.elementLocator(slider).getByRole('slider').element() as HTMLElement).focus();
    await userEvent.keyboard('{End}');
    expect(changes.map((detail) => detail.value)).toEqual([16]);
    await expect.element(page.elementLocator(slider).getByRole('slider')).toHaveValue('4');
  });
});

describe('rt-switch', () => {
  it('toggles by pointer and by Space, asking for the other state each time', async () => {
    const toggle = await mount('rt-switch', { name: 'shadows', label: 'Shadows', tooltip: 'Shadow rays', checked: false });
    const changes = record<CheckedDetail>(toggle, 'change');
    toggle.addEventListener('change', (event) => (toggle.checked = (event as CustomEvent<CheckedDetail>).detail.checked));
    const box = page.elementLocator(toggle).getByRole('switch', { name: 'Shadows' });
    await expect.element(box).not.toBeChecked();
    await userEvent.click(box);
    await expect.element(box).toBeChecked();
    await userEvent.keyboard(' ');
    await expect.element(box).not.toBeChecked();
    expect(changes).toEqual([{ checked: true }, { checked: false }]);
  });

  it('stays as its owner says when the owner refuses', async () => {
    const toggle = await mount('rt-switch', { name: 'shadows', label: 'Shadows', tooltip: 'Shadow rays', checked: false });
    const changes = record<CheckedDetail>(toggle, 'change');
    const box = page.elementLocator(toggle).getByRole('switch');
    await userEvent.click(box);
    expect(changes).toEqual([{ checked: true }]);
    await expect.element(box).not.toBeChecked();
  });
});

describe('rt-choice', () => {
  const options = [
    { value: 'grid', label: 'Grid' },
    { value: 'jittered', label: 'Jittered' },
    { value: 'random', label: 'Random' },
  ];

  it('chooses by pointer and moves the choice with the arrow keys', async () => {
    const choice = await mount('rt-choice', { name: 'samplePattern', label: 'Pattern', tooltip: 'Where the rays go', options, value: 'grid' });
    const changes = record<ValueDetail<string>>(choice, 'change');
    takeEveryChange(choice);
    const view = page.elementLocator(choice);
    await expect.element(view.getByRole('radio', { name: 'Grid' })).toBeChecked();
    await userEvent.click(view.getByRole('radio', { name: 'Random' }));
    await expect.element(view.getByRole('radio', { name: 'Random' })).toBeChecked();
    await userEvent.keyboard('{ArrowLeft}');
    await expect.element(view.getByRole('radio', { name: 'Jittered' })).toBeChecked();
    expect(changes.map((detail) => detail.value)).toEqual(['random', 'jittered']);
  });
});

describe('rt-vector-field', () => {
  const setup = { name: 'imageSize', label: 'Image size', tooltip: 'Pixels', axes: ['width', 'height'], min: 1, max: 4096, step: 1, unit: 'px', whole: true };

  it('changes one component and sends the whole vector', async () => {
    const field = await mount('rt-vector-field', { ...setup, value: [320, 240] });
    const changes = record<ValueDetail<number[]>>(field, 'change');
    const height = page.elementLocator(field).getByRole('textbox', { name: 'Image size height' });
    await expect.element(height).toHaveValue('240');
    await userEvent.fill(height, '180');
    await userEvent.keyboard('{Enter}');
    expect(changes.map((detail) => detail.value)).toEqual([[320, 180]]);
  });

  it('clamps a component out of range, with the reason for the limit', async () => {
    const field = await mount('rt-vector-field', { ...setup, value: [320, 240], limitReason: 'the browser runs out of memory' });
    const changes = record<ValueDetail<number[]>>(field, 'change');
    const width = page.elementLocator(field).getByRole('textbox', { name: 'Image size width' });
    await userEvent.fill(width, '10000');
    await userEvent.tab();
    expect(changes.map((detail) => detail.value)).toEqual([[4096, 240]]);
    await expect.element(page.elementLocator(field).getByText('Clamped to 1–4096: the browser runs out of memory')).toBeVisible();
  });

  it('goes back to its value on Escape', async () => {
    const field = await mount('rt-vector-field', { ...setup, value: [320, 240] });
    const changes = record<ValueDetail<number[]>>(field, 'change');
    const width = page.elementLocator(field).getByRole('textbox', { name: 'Image size width' });
    await userEvent.fill(width, '99');
    await userEvent.keyboard('{Escape}');
    await expect.element(width).toHaveValue('320');
    expect(changes).toEqual([]);
  });
});
