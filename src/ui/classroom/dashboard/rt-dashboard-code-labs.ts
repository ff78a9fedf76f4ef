import { msg } from '@lit/localize';
import { html, nothing } from 'lit';
import { summarizeCodeLabs } from '../../../classroom/dashboard-code-labs.ts';
import { LevelTableElement } from './level-table-element.ts';
import { namedRowsTableStyles, tableStyles } from './rt-dashboard-chart-styles.ts';

/**
 * @summary What the class made of a level's code labs (classroom/dashboard-code-labs.ts): per
 * lab the students who ran it, how many solved it, and the case kinds that failed first most
 * often (the misconceptions), with the runs each was first to fail in. Nothing when no
 * student ran a code lab of the level.
 */
export class RtDashboardCodeLabs extends LevelTableElement {
  static override styles = [tableStyles, namedRowsTableStyles];

  override render() {
    const labs = summarizeCodeLabs(this.records).filter((lab) => lab.level === this.level);
    if (labs.length === 0) return nothing;
    return html`<h3>${msg('Code labs')}</h3>
      <table>
        <caption>
          ${msg('Who solved each code lab, and the cases that failed first most often (the number of runs)')}
        </caption>
        <thead>
          <tr>
            <th scope="col">${msg('Task')}</th>
            <th scope="col" title=${msg('Students who ran the tests at least once')}>n</th>
            <th scope="col">${msg('Solved')}</th>
            <th scope="col">${msg('First failing case, most common first')}</th>
          </tr>
        </thead>
        <tbody>
          ${labs.map(
            (lab) =>
              html`<tr data-task=${lab.task}>
                <th scope="row">${this.taskName(lab.task)}</th>
                <td>${lab.learners}</td>
                <td>${lab.solved}</td>
                <td>${lab.failing.length === 0 ? '–' : lab.failing.map(({ kind, runs }) => `${kind} (${runs})`).join(', ')}</td>
              </tr>`,
          )}
        </tbody>
      </table>`;
  }
}

customElements.define('rt-dashboard-code-labs', RtDashboardCodeLabs);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-code-labs': RtDashboardCodeLabs;
  }
}
