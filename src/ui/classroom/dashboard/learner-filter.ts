import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import { assignmentsOf, classCodesOf, type ClassLearner, type LearnerFilter } from '../../../classroom/dashboard-learners.ts';
import { studentsCounted } from '../../../i18n/counted.ts';

/**
 * The dashboard's choosers for one assignment and one class, shown when the files hold more
 * than one of either; `pick` gets the changed part of the filter.
 */
export function learnerFilter(learners: readonly ClassLearner[], shown: number, filter: LearnerFilter, pick: (changes: Partial<LearnerFilter>) => void) {
  const assignments = assignmentsOf(learners);
  const classes = classCodesOf(learners);
  if (assignments.length < 2 && classes.length < 2) return nothing;
  const value = (text: string) => (text === '*' ? null : text);
  return html`<div class="filter">
    ${
      assignments.length < 2
        ? nothing
        : html`<label
          >${msg('Assignment')}
          <select name="assignment" @change=${(event: Event) => pick({ assignmentId: value((event.target as HTMLSelectElement).value) })}>
            <option value="*" ?selected=${filter.assignmentId === null}>${msg(str`All (${studentsCounted(learners.length)})`)}</option>
            ${assignments.map(
              (assignment) =>
                html`<option value=${assignment.id} ?selected=${filter.assignmentId === assignment.id}>
                  ${assignment.id === '' ? msg('Free play (no assignment)') : assignment.title} (${assignment.learners})
                </option>`,
            )}
          </select></label
        >`
    }
    ${
      classes.length < 2
        ? nothing
        : html`<label
          >${msg('Class')}
          <select name="class" @change=${(event: Event) => pick({ classCode: value((event.target as HTMLSelectElement).value) })}>
            <option value="*" ?selected=${filter.classCode === null}>${msg('All classes')}</option>
            ${classes.map((code) => html`<option value=${code} ?selected=${filter.classCode === code}>${code === '' ? msg('No class code') : code}</option>`)}
          </select></label
        >`
    }
    <span>${msg(str`${studentsCounted(shown)} shown.`)}</span>
  </div>`;
}
