import { msg } from '@lit/localize';
import { html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { loadBrowserCatalog, loadLevelTexts } from '../../app/level-catalog-browser.ts';
import { isSceneFragment } from '../../app/scene-link.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { decodeAssignment, isAssignmentFragment } from '../../classroom/assignment-link.ts';
import { previewedLevelId } from '../../classroom/level-preview.ts';
import { readSurveyPreview, SURVEY_PREVIEW } from '../../classroom/survey-preview-link.ts';
import { TEACHER_LINK_PREFIX } from '../../classroom/teacher-link.ts';
import { startLocale } from '../../i18n/locale.ts';
import { LazyModule } from '../../util/lazy-module.ts';
import '../controls/rt-load-problem.ts';
import '../lab/rt-lab.ts';
import { levelPreviewPage } from './level-preview-page.ts';
import { linkProblemText } from './link-problem-text.ts';
import './rt-link-notice.ts';
import './rt-scene-link-lab.ts';

/**
 * The teacher's pages, loaded when first opened: a student never needs them, and the QR
 * code maker and the dashboard's charts would make every student's first load heavier.
 * A page whose code cannot be loaded says so, with a Reload button, after a few tries.
 */
const TEACHER_PAGES: Record<string, { tag: string; code: LazyModule<unknown> }> = {
  '#/teacher': { tag: 'rt-teacher-page', code: new LazyModule(() => import('../classroom/rt-teacher-page.ts')) },
  '#/dashboard': { tag: 'rt-dashboard-page', code: new LazyModule(() => import('../classroom/dashboard/rt-dashboard-page.ts')) },
};

/** A teacher's preview of a survey (`#/survey/<id>`, linked from the teacher page): loaded like the teacher's pages. */
const SURVEY_PREVIEW_PAGE = { tag: 'rt-survey', code: new LazyModule(() => import('../classroom/rt-survey.ts')) };

/** The teacher page of the address: `#/teacher/a/…` is the teacher page opened on an assignment (classroom/teacher-link.ts). */
function teacherPage(route: string) {
  if (route.startsWith(SURVEY_PREVIEW)) return SURVEY_PREVIEW_PAGE;
  return TEACHER_PAGES[route.startsWith(TEACHER_LINK_PREFIX) ? '#/teacher' : route];
}

/** An assignment link as opened: the assignment, or why the learner plays freely instead. */
type Opened = { hash: string; assignment: Assignment | null; problem: string };

/**
 * @summary The app's top level: picks the page from the address's #fragment. The lab (with
 * the game) is the default; `#/teacher` is the teacher page; `#/dashboard` the class dashboard;
 * `#/s/<scene>` a shared scene in the lab; `#/survey/<id>` previews a survey; `#/preview/<level>` a level;
 * `#/a/<link>` opens a teacher's
 * assignment in the lab, or, when the link is damaged, free play with a message.
 */
export class RtApp extends LocalizedElement {
  static override properties = { route: { state: true }, opened: { state: true } };

  declare route: string;
  /** The assignment link last opened; null until it has been read (reading is asynchronous). */
  declare opened: Opened | null;
  private readonly onHashChange = () => (this.route = location.hash);

  constructor() {
    super();
    this.route = location.hash;
    this.opened = null;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    addEventListener('hashchange', this.onHashChange);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    removeEventListener('hashchange', this.onHashChange);
  }

  /** No shadow root: a router has no looks of its own, and pages stay reachable from the document. */
  protected override createRenderRoot(): HTMLElement {
    return this;
  }

  override willUpdate(): void {
    if (isAssignmentFragment(this.route) && this.opened?.hash !== this.route) void this.open(this.route);
    // Started once per page: a failed load stays failed (its message shows), it is not
    // started again by the render that shows it.
    const page = teacherPage(this.route);
    if (page?.code.state === 'idle')
      page.code.load().then(
        () => this.requestUpdate(),
        () => this.requestUpdate(),
      );
  }

  private async open(hash: string): Promise<void> {
    const result = await decodeAssignment(hash, loadBrowserCatalog());
    // The address may have changed while the link was read.
    if (hash !== this.route) return;
    // The assignment's language is the teacher's choice for the class: set before the lab renders.
    if (result.ok) await loadLevelTexts(await startLocale(result.assignment.locale));
    this.opened = { hash, assignment: result.ok ? result.assignment : null, problem: result.ok ? '' : linkProblemText(result) };
  }

  override render() {
    const page = teacherPage(this.route);
    if (page) {
      // A teacher's preview of a survey: nothing is saved.
      if (customElements.get(page.tag) && page === SURVEY_PREVIEW_PAGE) {
        const { surveyId, questions } = readSurveyPreview(this.route);
        return html`<rt-survey survey-id=${surveyId} .questions=${questions}></rt-survey>`;
      }
      if (customElements.get(page.tag))
        return page.tag === 'rt-teacher-page' ? html`<rt-teacher-page></rt-teacher-page>` : html`<rt-dashboard-page></rt-dashboard-page>`;
      if (page.code.state === 'failed')
        return html`<rt-load-problem .text=${msg('This page could not be loaded.')} .reason=${page.code.problem}></rt-load-problem>`;
      return html`<p class="loading" role="status">${msg('Loading…')}</p>`;
    }
    if (isSceneFragment(this.route)) return html`<rt-scene-link-lab .hash=${this.route}></rt-scene-link-lab>`;
    // A teacher's preview of one level (linked from the teacher page): nothing is saved.
    const previewed = previewedLevelId(this.route);
    if (previewed !== null) return levelPreviewPage(previewed);
    if (isAssignmentFragment(this.route)) {
      if (this.opened?.hash !== this.route) return nothing;
      const { assignment, problem } = this.opened;
      return assignment ? html`<rt-lab .assignment=${assignment}></rt-lab>` : html`<rt-link-notice .text=${problem}></rt-link-notice><rt-lab></rt-lab>`;
    }
    return html`<rt-lab></rt-lab>`;
  }
}

customElements.define('rt-app', RtApp);

declare global {
  interface HTMLElementTagNameMap {
    'rt-app': RtApp;
  }
}
