import type { ClassRecord } from '../../../classroom/dashboard-record.ts';
import { LocalizedElement } from '../../controls/localized-element.ts';

/**
 * A table of one level's page on the dashboard: the class's records, the level it is about,
 * and how a task's id reads as its title. The page sets all three.
 */
export class LevelTableElement extends LocalizedElement {
  static override properties = { records: { attribute: false }, level: {}, taskName: { attribute: false } };

  declare records: readonly ClassRecord[];
  declare level: string;
  /** A task's title in the page's language, from its id (the id itself when none is given). */
  declare taskName: (task: string) => string;

  constructor() {
    super();
    this.records = [];
    this.level = '';
    this.taskName = (task) => task;
  }
}
