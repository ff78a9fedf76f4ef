import { msg, str } from '@lit/localize';
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { Assignment } from '../../classroom/assignment.ts';
import { AssignmentShelf, newShelfId, type KeepResult, type SavedAssignment } from '../../classroom/saved-assignments.ts';
import { formatLocale } from '../../i18n/format-locale.ts';
import { refusingStorage, type KeyValueStorage } from '../../quest/saved-backups.ts';

/**
 * The teacher page's memory (classroom/saved-assignments.ts): which kept assignment the form
 * shows (`id`), the list to choose from, and a status that says "kept" only after the
 * browser stored it. The page calls `keep` with every assignment that makes a link.
 */
export class TeacherKeeper implements ReactiveController {
  entries: SavedAssignment[] = [];
  /** The kept assignment the form shows (a new one's id until it is first kept). */
  id = newShelfId();
  status = '';
  problem = false;
  private readonly shelf: AssignmentShelf;
  /** What was last kept under `id`, so that an unchanged assignment is not written (and re-dated) again. */
  private keptText = '';

  constructor(
    private readonly host: ReactiveControllerHost,
    storage: KeyValueStorage = browserStorage(),
  ) {
    host.addController(this);
    this.shelf = new AssignmentShelf(storage);
    const read = this.shelf.read();
    this.entries = read.entries;
    if (read.damaged > 0) {
      const count = read.damaged;
      this.status =
        read.backupKey === null
          ? msg(str`${count} kept assignment(s) could not be read and are left out; nothing is written over them.`)
          : msg(str`${count} kept assignment(s) could not be read and are left out; a copy of what was stored is kept in the browser.`);
      this.problem = true;
    }
  }

  hostConnected(): void {}

  /** The assignment last worked on, to open the page with: what a reload found lost before. */
  get latest(): SavedAssignment | undefined {
    return this.entries[0];
  }

  /** The form now shows `entry` (opened from the list). */
  show(entry: SavedAssignment): void {
    this.id = entry.id;
    this.keptText = JSON.stringify(entry.assignment);
    this.status = msg('Opened from this browser.');
    this.problem = false;
    this.host.requestUpdate();
  }

  /**
   * The form now shows a new assignment (new, copied or opened from a link): kept as a new
   * entry once it makes a link. `untouched`: a blank new one, kept only once it is changed, so
   * that opening the page or pressing "New assignment" leaves no empty entries behind.
   */
  startNew(untouched?: Assignment): void {
    this.id = newShelfId();
    this.keptText = untouched ? JSON.stringify(untouched) : '';
    this.status = untouched
      ? msg('A new assignment: it is kept in this browser once you change it.')
      : msg('Not kept yet: it is kept as soon as it makes a link.');
    this.problem = false;
    this.host.requestUpdate();
  }

  /** The assignment the form shows makes a link: kept under `id` (unless unchanged). */
  keep(assignment: Assignment): void {
    const text = JSON.stringify(assignment);
    if (text === this.keptText) return;
    this.tell(this.shelf.keep(this.id, assignment));
    if (this.problem) return;
    this.keptText = text;
    const time = new Intl.DateTimeFormat(formatLocale(), { timeStyle: 'short' }).format(new Date());
    this.status = msg(str`Kept in this browser (${time}).`);
  }

  /** The form's assignment cannot make a link yet: it is not kept (what was kept before stays). */
  notKept(): void {
    this.status = msg('Not kept yet: it is kept as soon as it makes a link.');
    this.problem = false;
  }

  /** Something the teacher asked of the list did not work (a link that did not open): said where the status shows. */
  tellProblem(text: string): void {
    this.status = text;
    this.problem = true;
    this.host.requestUpdate();
  }

  remove(id: string): void {
    this.tell(this.shelf.remove(id));
    if (!this.problem && id === this.id) {
      // The form still shows it: kept again only if it is changed.
      this.status = msg('Forgotten in this browser.');
    }
    this.host.requestUpdate();
  }

  private tell(result: KeepResult): void {
    this.entries = this.shelf.read().entries;
    this.problem = !result.ok;
    if (result.ok) return;
    this.status =
      result.kind === 'storage-full'
        ? msg("Not kept: the browser's storage is full. Copy the link: the link is the assignment.")
        : msg('Not kept: this browser does not let the page store data. Copy the link: the link is the assignment.');
  }
}

/** localStorage, or (blocked) a storage that refuses every write, so that nothing is said to be kept that was not. */
function browserStorage(): KeyValueStorage {
  try {
    return localStorage;
  } catch {
    return refusingStorage();
  }
}
