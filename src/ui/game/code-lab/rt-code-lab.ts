import { ContextConsumer } from '@lit/context';
import { msg, str } from '@lit/localize';
import type { EditorView } from 'codemirror';
import { css, html, nothing, type PropertyValues } from 'lit';
import type { CodeGoal } from '../../../quest/code-labs/code-goal.ts';
import { gradeLab, type LabReport, type Tolerance } from '../../../quest/code-labs/code-lab-grading.ts';
import { gradeSamples, sampleTally, type RandomRun, type StatisticsReport } from '../../../quest/code-labs/code-lab-statistics.ts';
import { drawCosineBounceFailure } from '../../../quest/code-labs/cosine-bounce-lab.ts';
import { directionTally, gradeDirections, type DirectionReport, type DirectionRun } from '../../../quest/code-labs/direction-statistics.ts';
import { labCases } from '../../../quest/code-labs/lab-cases.ts';
import { rendersWith } from '../../../quest/code-labs/lab-render/lab-functions.ts';
import { drawFailingCase } from '../../../quest/code-labs/lab-drawings.ts';
import { drawSampleRun } from '../../../quest/code-labs/pixel-samples-lab.ts';
import { LOCALES, localize, type Locale } from '../../../quest/localized-text.ts';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { gameStyles, taskPanelStyles } from '../game-styles.ts';
import { levelText } from '../level-text.ts';
import { createCodeEditor, replaceCode } from './code-editor.ts';
import { caseLegend, directionLegend, runLegend } from './case-legend.ts';
import { codeLabHostContext } from './code-lab-host.ts';
import { statisticsReport } from './code-lab-statistics-report.ts';
import { directionReport } from './direction-statistics-report.ts';
import { caseInput, caseKindName, failureText, sandboxUnavailableText, vectorLibrary } from './code-lab-texts.ts';
import { savedCode, saveCode } from './code-drafts.ts';
import { failedRun, LabSandbox, RUN_LIMIT_MS, type SandboxResult } from './lab-sandbox.ts';
import { labRenderPictures, renderLabPictures, type LabRenderState } from './lab-render-pictures.ts';
import { renderRandomLabPictures, rendersRandomly } from './random-lab-pictures.ts';

/** What the result area shows: nothing yet, a run under way, a graded run, or why a run gave no answers. */
type RunState =
  | { kind: 'idle' }
  | { kind: 'running' }
  | { kind: 'graded'; report: LabReport; tolerance: Tolerance }
  | { kind: 'sampled'; report: StatisticsReport; runs: RandomRun[] }
  | { kind: 'directions'; report: DirectionReport; runs: DirectionRun[] }
  | Exclude<SandboxResult, { kind: 'ran' }>;

/**
 * The last run's result per lab, for this visit: the task card shows a new panel once the task
 * is done (the run that passed), which should still say how that run went.
 */
const lastRuns = new Map<string, RunState>();

/**
 * @summary A code lab (spec/code-labs.md): the function's signature and contract, the vector
 * library, an editor holding the learner's code (kept per lab in this browser), **Run tests**
 * and the result: passes per kind of case and the first failing case spelled out; each run
 * is reported to the lab (codeLabHostContext). The code runs only on Run, in the sandbox
 * (lab-sandbox.ts). Loaded only when a level shows a code task.
 */
export class RtCodeLab extends LocalizedElement {
  static override properties = { goal: { attribute: false }, locale: {}, state: { state: true }, rendering: { state: true } };
  static override styles = [
    gameStyles,
    taskPanelStyles,
    css`
      code,
      .editor {
        font-family: ui-monospace, monospace;
      }
      .editor {
        border: 1px solid var(--rt-border);
        font-size: 0.85rem;
        max-height: 22rem;
        overflow: auto;
      }
      .editor .cm-editor {
        background: var(--rt-surface, white);
        color: var(--rt-text, black);
      }
      .buttons {
        display: flex;
        flex-wrap: wrap;
        gap: 6px;
        margin: 6px 0;
      }
      ul {
        margin: 4px 0;
        padding-left: 1.2em;
      }
      .fail {
        color: var(--rt-danger);
      }
      .pictures {
        display: flex;
        flex-wrap: wrap;
        gap: 6px;
      }
      figure {
        flex: 1 1 30%;
        margin: 0;
        min-width: 7rem;
      }
      canvas {
        border: 1px solid var(--rt-border);
        display: block;
        image-rendering: pixelated;
        width: 100%;
      }
      figcaption {
        font-size: 0.85rem;
      }
      .swatch {
        display: inline-block;
        width: 1em;
        height: 1em;
        margin-right: 0.25em;
        vertical-align: -0.15em;
        border: 1px solid var(--rt-border);
      }
    `,
  ];

  declare goal: CodeGoal | null;
  declare locale: Locale;
  declare private state: RunState;
  declare private rendering: LabRenderState;
  private readonly host = new ContextConsumer(this, { context: codeLabHostContext, subscribe: true });
  private readonly sandbox = new LabSandbox();
  private editor: EditorView | null = null;
  private code = '';

  constructor() {
    super();
    this.goal = null;
    this.locale = 'en';
    this.state = { kind: 'idle' };
    this.rendering = { kind: 'idle' };
  }

  override disconnectedCallback(): void {
    // The case belongs to this task: another task, or none, leaves the view to itself.
    this.host.value?.showCase(null);
    super.disconnectedCallback();
    this.sandbox.close();
    this.editor?.destroy();
    this.editor = null;
  }

  protected override willUpdate(changed: PropertyValues): void {
    if (changed.has('goal') && this.goal) {
      this.state = lastRuns.get(this.goal.code.lab) ?? { kind: 'idle' };
      this.rendering = { kind: 'idle' };
      this.drawCase(this.goal);
    }
  }

  /** The last run's first failing case (or run of samples) in the 3D view, or none (it passed, gave no answers, or there was no run). */
  private drawCase(goal: CodeGoal): void {
    this.host.value?.showCase(this.drawing(goal));
  }

  private drawing(goal: CodeGoal) {
    const state = this.state;
    if (state.kind === 'graded') return state.report.firstFailure && drawFailingCase(goal, state.report.firstFailure);
    if (state.kind === 'sampled') return state.report.firstFailure && drawSampleRun(state.report.firstFailure);
    if (state.kind === 'directions') return drawCosineBounceFailure(state.report, state.runs);
    return null;
  }

  protected override updated(changed: PropertyValues): void {
    const place = this.renderRoot.querySelector<HTMLElement>('.editor');
    if (!this.goal || !place) return;
    if (this.editor && !changed.has('goal') && !changed.has('locale')) return;
    const { lab, skeleton: skeletonText } = this.goal.code;
    const skeletons = LOCALES.map((locale) => localize(skeletonText, locale));
    const skeleton = localize(skeletonText, this.locale);
    // A new language keeps the code being written (the skeleton untouched: in the new
    // language); a new lab starts from its own.
    const written = this.editor && !changed.has('goal') ? this.editor.state.doc.toString() : savedCode(lab);
    this.code = written === null || skeletons.includes(written) ? skeleton : written;
    this.editor?.destroy();
    this.editor = createCodeEditor({
      parent: place,
      doc: this.code,
      label: msg('Your function: code editor'),
      syntaxError: msg('Syntax error: the browser cannot run this line as it is.'),
      onChange: (code) => {
        this.code = code;
        saveCode(lab, skeletons.includes(code) ? null : code);
      },
    });
  }

  override render() {
    const goal = this.goal;
    if (!goal) return nothing;
    const busy = this.state.kind === 'running' || this.rendering.kind === 'rendering';
    const canRender = (rendersWith(goal.code.lab) || rendersRandomly(goal.code.lab)) && this.host.value?.levelScene();
    return html`
      <section class="card" aria-labelledby="code-lab-title">
        <h3 id="code-lab-title">${msg('Code lab')}</h3>
        <p><code>${goal.code.signature}</code></p>
        <p>${levelText(goal.code.contract, this.locale)}</p>
        <details>
          <summary>${msg('Vector library')}</summary>
          <ul>
            ${vectorLibrary().map(([call, meaning]) => html`<li><code>${call}</code>: ${meaning}</li>`)}
          </ul>
          <p>${msg('Math.sqrt, Math.abs and the rest of Math work as in any JavaScript.')}</p>
        </details>
        <div class="editor"></div>
        <div class="buttons">
          <button class="primary" ?disabled=${busy} @click=${() => void this.run(goal)}>${msg('Run tests')}</button>
          ${canRender ? html`<button ?disabled=${busy} @click=${() => void this.renderScene(goal)}>${msg('Render with my function')}</button>` : nothing}
          <button @click=${() => this.reset(goal)}>${msg('Reset to skeleton')}</button>
        </div>
        <div role="status" aria-live="polite">${this.result()}</div>
        <div class="render" aria-live="polite">${labRenderPictures(this.rendering)}</div>
      </section>
    `;
  }

  private result() {
    const state = this.state;
    const seconds = RUN_LIMIT_MS / 1000;
    switch (state.kind) {
      case 'idle':
        return html`<p>${msg(str`Run tests runs your function on every case, for at most ${seconds} s.`)}</p>`;
      case 'running':
        return html`<p>${msg('Running your function…')}</p>`;
      case 'timeout':
        return html`<p class="fail">
          ${
            state.caseIndex === null
              ? msg(str`Your code did not finish within ${seconds} s, before the first case. Is there a loop that never ends?`)
              : msg(str`Your function did not return within ${seconds} s on case ${state.caseIndex + 1}. Is there a loop that never ends?`)
          }
        </p>`;
      case 'failed':
        return html`<p class="fail">
          ${state.line ? msg(str`Your code could not run: ${state.message} at line ${state.line}.`) : msg(str`Your code could not run: ${state.message}.`)}
        </p>`;
      case 'no-function':
        return html`<p class="fail">${msg(str`There is no function named ${state.name} in your code.`)}</p>`;
      case 'unavailable':
        return html`<p class="fail" role="alert">${sandboxUnavailableText()}</p>`;
      case 'graded':
        return this.report(state.report, state.tolerance);
      case 'sampled':
        return html`${statisticsReport(state.report, state.runs)} ${this.goal && this.drawing(this.goal) ? runLegend() : nothing}`;
      case 'directions':
        return html`${directionReport(state.report, state.runs)} ${state.report.firstFailure ? directionLegend() : nothing}`;
    }
  }

  private report(report: LabReport, tolerance: Tolerance) {
    const failure = report.firstFailure;
    const code = this.goal?.code;
    return html`
      <p class=${failure ? 'fail' : ''}>${msg(str`${report.passed} of ${report.total} cases pass.`)}</p>
      <ul>
        ${report.kinds.map(
          (kind) =>
            html`<li class=${kind.passed < kind.total ? 'fail' : ''}>${kind.passed === kind.total ? '✓' : '✗'} ${caseKindName(kind.kind)}: ${kind.passed}/${kind.total}</li>`,
        )}
      </ul>
      ${
        failure && code
          ? html`<p>
            <strong>${msg(str`First failing case: case ${failure.index + 1}, ${caseKindName(failure.labCase.kind)}.`)}</strong><br />
            <code>${caseInput(code.signature, failure.labCase.args)}</code><br />
            ${failureText(failure, code.lab, tolerance)}
          </p>
          ${this.goal && drawFailingCase(this.goal, failure) ? caseLegend(this.goal.code.lab, failure) : nothing}`
          : nothing
      }
    `;
  }

  private async run(goal: CodeGoal): Promise<void> {
    this.state = { kind: 'running' };
    const grading = labCases(goal);
    let result: SandboxResult;
    try {
      const args = grading.kind === 'cases' ? grading.cases.map((labCase) => labCase.args) : grading.runs.map((run) => run.args);
      result = await this.sandbox.run(this.code, goal.code.function, args);
    } catch (error) {
      this.sandbox.close();
      result = failedRun(error);
    }
    if (result.kind !== 'ran') {
      this.state = result;
      lastRuns.set(goal.code.lab, result);
      this.drawCase(goal);
      return;
    }
    if (grading.kind === 'statistics') {
      const report = gradeSamples(grading.runs, result.outcomes, grading.significance);
      this.state = { kind: 'sampled', report, runs: grading.runs };
      lastRuns.set(goal.code.lab, this.state);
      this.drawCase(goal);
      this.host.value?.graded({ lab: goal.code.lab, ...sampleTally(report) });
      return;
    }
    if (grading.kind === 'directions') {
      const report = gradeDirections(grading.runs, result.outcomes, grading.significance);
      this.state = { kind: 'directions', report, runs: grading.runs };
      lastRuns.set(goal.code.lab, this.state);
      this.drawCase(goal);
      this.host.value?.graded({ lab: goal.code.lab, ...directionTally(report, grading.normals) });
      return;
    }
    const { tolerance } = grading;
    const report = gradeLab(grading.cases, result.outcomes, tolerance);
    this.state = { kind: 'graded', report, tolerance };
    lastRuns.set(goal.code.lab, this.state);
    this.drawCase(goal);
    const failure = report.firstFailure;
    this.host.value?.graded({ lab: goal.code.lab, passed: report.passed, total: report.total, failed: failure?.labCase.kind ?? null });
  }

  /** Renders the level's scene with the learner's function beside the tracer's (lab-render-pictures.ts, random-lab-pictures.ts); the code runs only in the sandbox. */
  private async renderScene(goal: CodeGoal): Promise<void> {
    const scene = this.host.value?.levelScene();
    const grading = labCases(goal);
    const lab = goal.code.lab;
    if (!scene) return;
    let render: (() => Promise<LabRenderState>) | null = null;
    if (rendersRandomly(lab)) render = () => renderRandomLabPictures(goal, lab, scene, this.code, this.sandbox);
    else if (grading.kind === 'cases' && rendersWith(lab)) render = () => renderLabPictures(goal, lab, grading.tolerance, scene, this.code, this.sandbox);
    if (!render) return;
    this.rendering = { kind: 'rendering' };
    // Let the panel say so before the first pass keeps the page busy.
    await this.updateComplete;
    const rendered = await render();
    // Another task opened meanwhile: these pictures are not of its lab.
    if (this.goal === goal) this.rendering = rendered;
  }

  private reset(goal: CodeGoal): void {
    if (!this.editor || !confirm(msg('Replace your code with the skeleton? Your code is lost.'))) return;
    replaceCode(this.editor, localize(goal.code.skeleton, this.locale));
  }
}

customElements.define('rt-code-lab', RtCodeLab);

declare global {
  interface HTMLElementTagNameMap {
    'rt-code-lab': RtCodeLab;
  }
}
