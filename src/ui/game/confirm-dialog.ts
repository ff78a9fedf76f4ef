import { css, html, type TemplateResult } from 'lit';

/**
 * The Menu's "are you sure?" for what cannot be undone (reset, withdraw): a modal dialog with
 * a heading, what will happen, and two buttons, "Cancel" (focused first, so Enter does not
 * delete) and the red one that does it. Its styles include `button.danger`, for the button
 * that opens it as well.
 */
export const confirmDialogStyles = css`
  dialog {
    max-width: 400px;
    border: 1px solid var(--rt-border);
    border-radius: var(--rt-radius);
    background: var(--rt-surface);
    color: var(--rt-text);
  }
  .actions {
    display: flex;
    gap: 8px;
    justify-content: flex-end;
  }
  button.danger {
    border-color: var(--rt-danger);
    color: var(--rt-danger);
  }
`;

export interface ConfirmDialog {
  /** The dialog's class, for `askToConfirm`. */
  name: string;
  title: string;
  body: TemplateResult;
  cancel: string;
  /** The red button's label. */
  confirm: string;
  /** Called once the dialog has closed with the red button (not with Cancel or Escape). */
  confirmed: () => void;
}

export function confirmDialog({ name, title, body, cancel, confirm, confirmed }: ConfirmDialog): TemplateResult {
  return html`<dialog class=${name} aria-labelledby=${`${name}-title`} @close=${(event: Event) => (event.target as HTMLDialogElement).returnValue === 'confirm' && confirmed()}>
    <h3 id=${`${name}-title`}>${title}</h3>
    ${body}
    <form method="dialog" class="actions">
      <button value="cancel" autofocus>${cancel}</button>
      <button value="confirm" class="danger">${confirm}</button>
    </form>
  </dialog>`;
}

/** Opens the dialog `name` in `root`. Its answer is cleared first: Escape leaves the last one. */
export function askToConfirm(root: ParentNode, name: string): void {
  const dialog = root.querySelector<HTMLDialogElement>(`dialog.${name}`);
  if (!dialog) return;
  dialog.returnValue = '';
  dialog.showModal();
}
