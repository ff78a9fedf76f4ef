// The pupil's classroom screens that inform and ask: the consent text before the code, the
// participant code, "Withdraw and delete my data" and the note over a teacher's preview.
// Reached only through properties, events and what a user sees (roles and labels).
import { afterEach, describe, expect, it } from 'vitest';
import { page, userEvent } from 'vitest/browser';
import type { WithdrawReport } from '../../src/app/withdraw-data.ts';
import '../../src/ui/game/rt-participant-dialog.ts';
import '../../src/ui/game/rt-progress-menu.ts';
import type { ProgressCommand } from '../../src/ui/game/rt-progress-menu.ts';
import '../../src/ui/game/rt-withdraw.ts';
import '../../src/ui/shell/rt-link-notice.ts';
import '../../src/ui/shell/rt-preview-notice.ts';
import { mount, record, unmountAll } from './mount.ts';

afterEach(unmountAll);

describe('rt-participant-dialog', () => {
  it('shows the consent text first, each paragraph apart, and asks for the code only after "I understand, start"', async () => {
    const dialog = await mount('rt-participant-dialog', { heading: 'Welcome to 5H2', consent: 'We keep your answers.\n\nYou may stop at any time.' });
    const view = page.elementLocator(dialog);
    const codes = record<string>(dialog, 'participant-code');
    await expect.element(view.getByRole('heading', { name: 'Before you start' })).toBeVisible();
    expect([...dialog.shadowRoot!.querySelectorAll('.consent p')].map((paragraph) => paragraph.textContent)).toEqual([
      'We keep your answers.',
      'You may stop at any time.',
    ]);
    expect(dialog.shadowRoot!.querySelector('input[name=code]')).toBeNull();

    await view.getByRole('button', { name: 'I understand, start' }).click();
    const field = view.getByRole('textbox', { name: 'Participant code' });
    await field.fill('5h2 03');
    await userEvent.keyboard('{Enter}');
    expect(codes).toEqual([]);
    await expect.element(view.getByRole('alert')).toHaveTextContent('Use letters, digits, - or _');
    await field.fill('5h2-03');
    await view.getByRole('button', { name: 'Start', exact: true }).click();
    expect(codes).toEqual(['5H2-03']);
  });

  it('asks for the code at once when the assignment has no consent text', async () => {
    const dialog = await mount('rt-participant-dialog', {});
    await expect.element(page.elementLocator(dialog).getByRole('textbox', { name: 'Participant code' })).toBeVisible();
    expect(dialog.shadowRoot!.querySelector('.consent')).toBeNull();
  });
});

describe('rt-withdraw', () => {
  /** The report dialog reloads the page when it closes ("Start again"): not in a test. */
  function keepPage(element: HTMLElement): void {
    const report = element.shadowRoot!.querySelector('dialog.report')!;
    report.addEventListener('close', (event) => event.stopImmediatePropagation(), { capture: true });
  }

  /** Asks to withdraw, confirms, and answers the command with `report`, as the quest controller does. */
  async function withdrawWith(report: WithdrawReport) {
    const withdraw = await mount('rt-withdraw', {});
    keepPage(withdraw);
    const commands = record<ProgressCommand>(withdraw, 'progress-command');
    const view = page.elementLocator(withdraw);
    await view.getByRole('button', { name: 'Withdraw and delete my data…' }).click();
    await view.getByRole('button', { name: 'Delete my data', exact: true }).click();
    expect(commands.map((command) => command.kind)).toEqual(['withdraw']);
    (commands[0] as Extract<ProgressCommand, { kind: 'withdraw' }>).done(report);
    return { withdraw, done: view.getByRole('dialog', { name: 'Your data was deleted' }) };
  }

  it('deletes nothing when the learner cancels', async () => {
    const withdraw = await mount('rt-withdraw', {});
    const commands = record<ProgressCommand>(withdraw, 'progress-command');
    const view = page.elementLocator(withdraw);
    await view.getByRole('button', { name: 'Withdraw and delete my data…' }).click();
    await expect.element(view.getByRole('dialog', { name: 'Withdraw and delete your data?' })).toBeVisible();
    await view.getByRole('button', { name: 'Cancel' }).click();
    await expect.element(view.getByRole('dialog', { name: 'Withdraw and delete your data?' })).not.toBeInTheDocument();
    expect(commands).toEqual([]);
  });

  it('asks, sends the withdraw command, then says what was deleted', async () => {
    const { withdraw, done } = await withdrawWith({ progress: true, session: true, survey: false, conceptTest: true, backups: 2, failed: [] });
    await expect.element(done).toBeVisible();
    expect([...withdraw.shadowRoot!.querySelectorAll('dialog.report li')].map((item) => item.textContent)).toEqual([
      'your progress and the record of what you did',
      'your participant code',
      'your concept test answers',
      '2 backups',
    ]);
    await expect.element(done).not.toHaveTextContent('The browser refused');
  });

  it('says when the browser refused to delete some of it', async () => {
    const { done } = await withdrawWith({ progress: false, session: false, survey: false, conceptTest: false, backups: 0, failed: ['rtq.progress'] });
    await expect.element(done).toHaveTextContent('There was nothing saved in this browser to delete.');
    await expect.element(done).toHaveTextContent("The browser refused to delete some of it: clear this site's data in the browser's settings.");
  });
});

describe('rt-preview-notice', () => {
  it('says that nothing of the preview is kept, until dismissed', async () => {
    const notice = await mount('rt-preview-notice', {});
    const view = page.elementLocator(notice);
    await expect.element(view.getByRole('status')).toHaveTextContent('Preview of one level');
    await expect.element(view.getByRole('status')).toHaveTextContent('Nothing is saved');
    await view.getByRole('button', { name: 'Dismiss message' }).click();
    await expect.element(view.getByRole('status')).not.toBeInTheDocument();
    expect(notice.dismissed).toBe(true);
  });
});

describe('rt-link-notice', () => {
  it('shows why a link did not open until dismissed, and again for the next problem', async () => {
    const notice = await mount('rt-link-notice', { text: 'This assignment link is damaged.' });
    const view = page.elementLocator(notice);
    await expect.element(view.getByRole('alert')).toHaveTextContent('This assignment link is damaged.');
    await view.getByRole('button', { name: 'Dismiss message' }).click();
    await expect.element(view.getByRole('alert')).not.toBeInTheDocument();
    notice.text = 'This link is for another version of the game.';
    await expect.element(view.getByRole('alert')).toHaveTextContent('another version of the game');
  });

  it('shows nothing without a text', async () => {
    const notice = await mount('rt-link-notice', {});
    expect(notice.shadowRoot!.querySelector('[role=alert]')).toBeNull();
  });
});

describe("rt-progress-menu's reset", () => {
  it('resets only after "Reset" in its confirmation, not after Cancel', async () => {
    const menu = await mount('rt-progress-menu', {});
    const commands = record<ProgressCommand>(menu, 'progress-command');
    const view = page.elementLocator(menu);
    await view.getByRole('button', { name: /Menu/ }).click();
    await view.getByRole('button', { name: 'Reset progress…' }).click();
    const confirm = view.getByRole('dialog', { name: 'Reset all progress?' });
    await confirm.getByRole('button', { name: 'Cancel' }).click();
    await expect.element(confirm).not.toBeInTheDocument();
    expect(commands).toEqual([]);
    // The modal dialog closed the Menu's popover: it is opened again, as a learner would.
    await view.getByRole('button', { name: /Menu/ }).click();
    await view.getByRole('button', { name: 'Reset progress…' }).click();
    await confirm.getByRole('button', { name: 'Reset', exact: true }).click();
    expect(commands).toEqual([{ kind: 'reset' }]);
  });
});
