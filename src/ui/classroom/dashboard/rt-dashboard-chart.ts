import { LocalizedElement } from '../../controls/localized-element.ts';
/**
 * What every dashboard chart takes: its rows (one per task or question) and a caption that
 * says what it shows, for screen readers.
 */
export class DashboardChart<Row> extends LocalizedElement {
  static override properties = { rows: { attribute: false }, caption: {} };

  declare rows: readonly Row[];
  declare caption: string;

  constructor() {
    super();
    this.rows = [];
    this.caption = '';
  }
}
