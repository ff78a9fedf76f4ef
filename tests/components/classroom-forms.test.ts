// The classroom's forms: the concept test page and the closing survey a pupil hands in, and
// the dashboard's class list a teacher pastes codes into. Reached through properties, events and what a user sees.
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { page, userEvent } from 'vitest/browser';
import type { ConceptItem } from '../../src/classroom/concept-test/concept-bank-schema.ts';
import { formItems, loadConceptBank } from '../../src/classroom/concept-test/concept-bank.ts';
import { readClassFiles } from '../../src/classroom/dashboard-class.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import { localize } from '../../src/quest/localized-text.ts';
import '../../src/ui/classroom/dashboard/rt-dashboard-class-list.ts';
import { CLASS_LIST_KEY } from '../../src/ui/classroom/dashboard/rt-dashboard-class-list.ts';
import '../../src/ui/classroom/rt-concept-test.ts';
import type { ConceptTestHandIn } from '../../src/ui/classroom/rt-concept-test.ts';
import '../../src/ui/classroom/rt-survey.ts';
import type { SurveySubmission } from '../../src/classroom/survey-answers.ts';
import { surveyById } from '../../src/classroom/surveys.ts';
import { simulatedExport } from '../support/class-exports.ts';
import { mount, record, unmountAll } from './mount.ts';

afterEach(unmountAll);

describe('rt-concept-test', () => {
  let items: ConceptItem[] = [];
  beforeEach(async () => {
    const bank = await loadConceptBank();
    if (!bank) throw new Error('the concept bank did not load');
    items = formItems(bank, 'B');
  });

  const question = (page: HTMLElement, item: ConceptItem) => page.shadowRoot!.querySelector<HTMLFieldSetElement>(`fieldset[data-question="${item.id}"]`)!;

  it('asks every question of its form, and hands in nothing while one is open', async () => {
    const test = await mount('rt-concept-test', { phase: 'post', form: 'B', seed: 'attempt-1', locale: 'en' });
    const handedIn = record<ConceptTestHandIn>(test, 'concept-test-submitted');
    const view = page.elementLocator(test);
    await expect.element(view.getByRole('heading', { name: 'You are done: the questions once more' })).toBeVisible();
    expect([...test.shadowRoot!.querySelectorAll('legend')].map((legend) => legend.textContent)).toEqual(
      items.map((item, index) => `${index + 1}. ${localize(item.question, 'en')}`),
    );

    question(test, items[0]!).querySelector('input')!.click();
    await view.getByRole('button', { name: 'Hand in' }).click();
    expect(handedIn).toEqual([]);
    await expect.element(view.getByRole('alert')).toHaveTextContent(`${items.length - 1} questions have no answer yet.`);
    expect(items.map((item) => question(test, item).getAttribute('aria-invalid'))).toEqual(items.map((_, index) => String(index > 0)));
  });

  it('hands in the choice each answer was, in the shuffled order the pupil saw', async () => {
    const test = await mount('rt-concept-test', { phase: 'post', form: 'B', seed: 'attempt-1', locale: 'en' });
    const handedIn = record<ConceptTestHandIn>(test, 'concept-test-submitted');
    const clicked: Record<string, string> = {};
    for (const item of items) {
      // The last choice on screen: which of the item's choices that is depends on the shuffle.
      const labels = [...question(test, item).querySelectorAll('label')];
      const label = labels[labels.length - 1]!;
      label.querySelector('input')!.click();
      clicked[item.id] = label.textContent!.trim();
    }
    await test.updateComplete;
    expect(test.shadowRoot!.querySelector('[aria-invalid="true"]')).toBeNull();
    await page.elementLocator(test).getByRole('button', { name: 'Hand in' }).click();
    expect(handedIn).toHaveLength(1);
    const { phase, submission } = handedIn[0]!;
    expect([phase, submission.form]).toEqual(['post', 'B']);
    expect(Object.keys(submission.answers)).toEqual(items.map((item) => item.id));
    for (const item of items) {
      const chosen = item.choices.find((choice) => choice.id === submission.answers[item.id]);
      expect(chosen && localize(chosen.text, 'en')).toBe(clicked[item.id]);
    }
  });
});

describe('rt-survey', () => {
  /** The teacher ticked only the minutes and the (optional) age. */
  const choice = Object.fromEntries(surveyById('default')!.questions.map((question) => [question.id, question.id === 'minutes' || question.id === 'age']));

  it("asks only the teacher's questions, says what is wrong under the question, and hands in once it is right", async () => {
    const survey = await mount('rt-survey', { surveyId: 'default', locale: 'en', levels: ['01-look-around'], choice });
    const view = page.elementLocator(survey);
    const handedIn = record<SurveySubmission>(survey, 'survey-submitted');
    expect([...survey.shadowRoot!.querySelectorAll('fieldset')].map((card) => card.dataset['question'])).toEqual(['minutes', 'age']);

    await view.getByRole('button', { name: 'Hand in' }).click();
    await expect.element(view.getByRole('alert')).toHaveTextContent('1 answer still needs attention.');
    const minutes = view.getByRole('textbox', { name: 'About how many minutes did you spend on the game?' });
    // The first question with a problem has the focus (inside the survey's shadow root).
    expect(survey.shadowRoot!.activeElement).toBe(minutes.element());
    const card = view.getByRole('group', { name: /About how many minutes/ });
    await expect.element(card).toHaveAttribute('aria-invalid', 'true');
    await expect.element(card).toHaveTextContent('Please answer this question.');
    expect(handedIn).toEqual([]);

    await minutes.fill('half an hour');
    await userEvent.tab(); // the field reads its text when it is left, as a pupil does
    await view.getByRole('button', { name: 'Hand in' }).click();
    await expect.element(card).toHaveTextContent('Please type a number, like 25.');
    await minutes.fill('25');
    await userEvent.tab();
    await view.getByRole('button', { name: 'Hand in' }).click();
    expect(handedIn.map((submission) => submission.answers)).toEqual([{ minutes: 25 }]);
    await expect.element(view.getByRole('status')).toHaveTextContent('Thank you for your answers.');
  });
});

describe('rt-dashboard-class-list', () => {
  beforeEach(() => localStorage.removeItem(CLASS_LIST_KEY));
  afterEach(() => localStorage.removeItem(CLASS_LIST_KEY));

  const learners = classLearners(
    readClassFiles(
      ['5H2-01', '5h2-02', '5H2-09'].map((code, index) => ({
        name: `ray-tracer-quest-${code}.json`,
        text: JSON.stringify({ ...simulatedExport(index), participant: code, learner: { ...simulatedExport(index).learner, id: code } }),
      })),
    ).records,
  );

  it('asks for the list until codes are pasted, then says who handed in, who is missing and who is not on it', async () => {
    const list = await mount('rt-dashboard-class-list', { learners });
    const view = page.elementLocator(list);
    await expect.element(view.getByText('Paste the class list to see who has handed in')).toBeVisible();
    await view.getByRole('textbox', { name: 'Participant codes you handed out, one per line' }).fill('5H2-01\n5H2-02\n\n5h2-03\n');
    await expect.element(view.getByText('2 of 3 handed in, 1 missing.')).toBeVisible();
    const names = (selector: string) => [...list.shadowRoot!.querySelectorAll(`${selector} li`)].map((item) => item.textContent!.replace(/\s+/g, ' ').trim());
    expect(names('.missing')).toEqual(['5h2-03']); // as pasted
    expect(names('.handed-in')).toEqual(['5H2-01 (ray-tracer-quest-5H2-01.json)', '5H2-02 (ray-tracer-quest-5h2-02.json)']);
    expect(names('.not-on-list')).toEqual(['5H2-09 (ray-tracer-quest-5H2-09.json)']);
  });

  it('lists a result without a participant code as not on the list, and asks again once the list is cleared', async () => {
    const anonymous = classLearners(
      readClassFiles([
        {
          name: 'results.json',
          text: JSON.stringify({ ...simulatedExport(5), participant: null, learner: { ...simulatedExport(5).learner, id: 'install:abc' } }),
        },
      ]).records,
    );
    const list = await mount('rt-dashboard-class-list', { learners: [...learners, ...anonymous] });
    const view = page.elementLocator(list);
    const box = view.getByRole('textbox', { name: 'Participant codes you handed out, one per line' });
    await box.fill('5H2-01');
    await expect.element(view.getByText('1 of 1 handed in, 0 missing.')).toBeVisible();
    await expect.element(view.getByRole('heading', { name: 'Not on the list (3)' })).toBeVisible();
    expect(list.shadowRoot!.querySelector('.not-on-list')!.textContent).toContain('(no code) (results.json)');
    await box.fill('');
    await expect.element(view.getByText('Paste the class list to see who has handed in')).toBeVisible();
    expect(localStorage.getItem(CLASS_LIST_KEY)).toBe('');
  });

  it('keeps the pasted list in this browser for the next visit', async () => {
    const first = await mount('rt-dashboard-class-list', { learners });
    await page.elementLocator(first).getByRole('textbox').fill('5H2-01\n5H2-04');
    unmountAll();
    const next = await mount('rt-dashboard-class-list', { learners });
    const view = page.elementLocator(next);
    await expect.element(view.getByRole('textbox')).toHaveValue('5H2-01\n5H2-04');
    await expect.element(view.getByText('1 of 2 handed in, 1 missing.')).toBeVisible();
  });
});
