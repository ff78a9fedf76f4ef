import { showLocaleProblem } from '../controls/locale-problem.ts';
import { msg, str } from '@lit/localize';
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { levelTextsLocale, loadBrowserCatalog } from '../../app/level-catalog-browser.ts';
import { damagedSaveFileName } from '../../app/damaged-saves.ts';
import { QuestSession } from '../../app/quest-session.ts';
import { followInLearningPlatform } from '../../app/learning-platform.ts';
import { deleteAssignmentData } from '../../app/withdraw-data.ts';
import type { SaveProblemKind } from '../../quest/progress-store.ts';
import type { ShowMeStage } from '../../app/show-me-player.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import type { SurveySubmission } from '../../classroom/survey-answers.ts';
import { chooseLocale, currentLocale } from '../../i18n/locale.ts';
import { issueText } from '../../i18n/issue-text.ts';
import { labCodeImportText } from '../../i18n/lab-code-import-text.ts';
import { contextDamageText, placesOf, progressProblemText, saveProblemReason, saveProblemText, surveyDamageText } from '../../i18n/progress-problem-text.ts';
import { localNumbers } from '../../i18n/number-format.ts';
import { shortList } from '../../i18n/short-list.ts';
import type { Store } from '../../lab-state/store.ts';
import { MemoryStorage, refusingStorage, type KeyValueStorage } from '../../quest/saved-backups.ts';
import type { Scene } from '../../scene/scene.ts';
import { downloadText } from '../../util/download-file.ts';
import type { QuestCommand } from '../game/quest-command.ts';
import type { MapChoice } from '../game/rt-level-map.ts';
import type { ProgressCommand } from '../game/rt-progress-menu.ts';
import { conceptBankNow, loadConceptBank } from '../../classroom/concept-test/concept-bank.ts';

/** A file's size in a message, from its characters (what localStorage counts): "3 kB", "9.2 MB". */
const SIZE = localNumbers({ maximumFractionDigits: 1 });
function fileSize(characters: number): string {
  return characters < 1e6 ? `${SIZE.format(Math.max(1, Math.round(characters / 1e3)))} kB` : `${SIZE.format(characters / 1e6)} MB`;
}

/** What was left out of progress read with damaged parts (progress-salvage.ts), as a sentence to add; '' when nothing was. */
function leftOut(repaired: readonly string[]): string {
  if (repaired.length === 0) return '';
  const left = repaired.length;
  return ` ${msg(str`What was damaged in it is left out (${left}: ${shortList(placesOf(repaired), 3, ', ')}).`)}`;
}

/** The address fragment that opens the free lab instead of the game. */
export const FREE_LAB_HASH = '#free-lab';

/**
 * localStorage; when the browser blocks it, a storage that refuses every write, so that the
 * session says progress is not saved (and keeps it for this visit) instead of "saving" it
 * into memory.
 */
function browserStorage(): KeyValueStorage {
  try {
    return localStorage;
  } catch {
    return refusingStorage();
  }
}

/** What the game needs of the lab it plays in. */
export interface QuestHost extends ReactiveControllerHost {
  readonly store: Store;
  /** The teacher's assignment, if the lab was opened from one. */
  readonly assignment: Assignment | null;
  /** "Show me" performs solutions through this: the real view, the real render window. */
  readonly stage: ShowMeStage;
  toast(text: string, tone?: 'info' | 'error'): void;
  /** The render window closes (a level or the free lab opens). */
  closeRenderWindow(): void;
  /** The game switched between a level, the map and the free lab. */
  modeChanged(freeLab: boolean): void;
}

/**
 * The game in the lab: starts the quest session (progress from storage, then resume, the
 * first level or the map), and turns the task column's, the level map's and the menu's
 * commands into session calls. Holds the newcomer's welcome and the closing survey's answers.
 */
export class QuestController implements ReactiveController {
  session: QuestSession | null = null;
  /** A newcomer's welcome, shown once over the first level's tasks. */
  welcome = false;
  /**
   * A newcomer whose welcome has not been shown yet: it waits for the first level to open
   * (after the participant code dialog, in an assignment that asks for one).
   */
  private welcomeDue = false;
  /** Why the session record was damaged, for the participant code dialog (it is asked again then), or ''. */
  contextNote = '';
  /** The save problem last told, so that each is told once when it starts, and its end too. */
  private toldSaveProblem: SaveProblemKind | null = null;
  /** The learner put the closing survey off ("Later"): it waits in the task column instead of covering the lab. */
  surveyLater = false;
  private readonly cleanup: (() => void)[] = [];

  constructor(private readonly host: QuestHost & HTMLElement) {
    host.addController(this);
  }

  hostConnected(): void {
    this.start();
  }

  hostDisconnected(): void {
    this.stop();
  }

  /** The game: progress from storage (a message if it was damaged), then resume, the first level or the map. */
  start(): void {
    this.stop();
    // An assignment with a concept test waits for its item bank, loaded apart from the first screen.
    if (this.host.assignment?.conceptTest && !conceptBankNow()) {
      void loadConceptBank().then(() => this.host.isConnected && this.start());
      return;
    }
    const catalog = loadBrowserCatalog();
    // A teacher's preview of a level (the lab's `preview` attribute, classroom/level-preview.ts) keeps nothing.
    const storage = this.host.hasAttribute('preview') ? new MemoryStorage() : browserStorage();
    const session = new QuestSession({ store: this.host.store, catalog, storage, assignment: this.host.assignment });
    this.session = session;
    // The level texts speak the app's language (an address's ?lang= or the menu's choice may differ from the saved one).
    if (session.locale !== currentLocale()) session.setLocale(currentLocale());
    this.cleanup.push(
      session.subscribe(() => this.changed()),
      session.attach(document),
      followInLearningPlatform(session, window),
      () => session.dispose(),
    );
    const damage = session.contextDamage;
    this.contextNote = damage
      ? contextDamageText({
          codeLost: damage.lost.includes('participant-code') && session.needsParticipantCode,
          attemptLost: damage.lost.includes('attempt'),
          backedUp: damage.backupKey !== null,
        })
      : '';
    const surveyDamage = session.survey.damage;
    const surveyNote = surveyDamage
      ? surveyDamageText({
          askedAgain: session.survey.submission === null,
          kept: Object.keys(session.survey.submission?.answers ?? {}).length,
          leftOut: surveyDamage.cut || surveyDamage.lost.includes('answers') ? null : surveyDamage.lost.length,
          backedUp: surveyDamage.backupKey !== null,
        })
      : undefined;
    // A held damaged save is told by the messages below already.
    const toldHeld = session.problem?.backupKey === null || damage?.backupKey === null || surveyDamage?.backupKey === null;
    this.toldSaveProblem = toldHeld && session.saveProblem === 'damaged-held' ? 'damaged-held' : null;
    const problems = [
      session.problem && progressProblemText(session.problem, session.engine.points),
      this.contextNote || undefined,
      surveyNote,
      catalog.errors.length > 0 ? msg(str`The level list could not be read: ${catalog.errors.map(issueText).join('; ')}`) : undefined,
    ];
    // The toast is on the page after the first render.
    void this.host.updateComplete.then(() => problems.forEach((problem) => problem && this.host.toast(problem, 'error')));
    const newcomer = Object.keys(session.engine.progress.levels).length === 0 && session.engine.progress.current === null;
    // #free-lab (a bookmark, the lab's own browser tests) goes straight to the free lab,
    // also when it is pasted into a tab the game is open in: a new fragment loads no page.
    if (location.hash === FREE_LAB_HASH) session.openFreeLab();
    else session.start();
    const onHashChange = () => {
      if (location.hash === FREE_LAB_HASH) this.map({ kind: 'free-lab' });
    };
    addEventListener('hashchange', onHashChange);
    this.cleanup.push(() => removeEventListener('hashchange', onHashChange));
    this.welcome = false;
    this.welcomeDue = newcomer;
    this.changed();
  }

  /** A shared scene in the free lab (every panel, to look at it and save it); the learner's sandbox is kept until they edit it. */
  openSharedScene(scene: Scene): void {
    if (!this.session) return;
    this.session.openFreeLab();
    this.host.store.dispatch({ type: 'scene.loaded', scene });
  }

  private stop(): void {
    for (const stop of this.cleanup.splice(0)) stop();
    this.session = null;
  }

  private changed(): void {
    // Left the free lab a #free-lab address opened: the address no longer says so, so that a
    // reload returns to the game where the learner is, and the same link pasted again opens it.
    if (this.session && this.session.mode.kind !== 'free-lab' && location.hash === FREE_LAB_HASH)
      history.replaceState(history.state, '', location.pathname + location.search);
    if (this.welcomeDue && this.session?.mode.kind === 'level') {
      this.welcomeDue = false;
      this.welcome = true;
    }
    this.tellSaveProblem();
    this.host.modeChanged(this.session?.mode.kind === 'free-lab');
    this.host.requestUpdate();
  }

  quest(command: QuestCommand): void {
    const session = this.session;
    if (!session) return;
    const engine = session.engine;
    switch (command.kind) {
      case 'next':
        engine.next();
        return;
      case 'predict':
        engine.predict(command.task, command.prediction);
        return;
      case 'reflect':
        engine.reflect(command.task, command.prediction);
        return;
      case 'continue':
        engine.continueAfterReveal(command.task);
        return;
      case 'hint':
        engine.askHint(command.task);
        return;
      case 'show-me':
        return session.showMe(command.task, this.host.stage);
      case 'skip':
        engine.skip(command.task);
        return;
      case 'explain':
        engine.expandExplanation(command.task);
        return;
      case 'next-level': {
        const next = session.nextLevel();
        if (next) this.openLevel(next);
        return;
      }
      case 'map':
        return session.openMap();
    }
  }

  openLevel(id: string): void {
    this.host.closeRenderWindow();
    this.welcome = false;
    const opened = this.session?.openLevel(id);
    if (opened && !opened.ok)
      this.host.toast(
        opened.reason === 'locked'
          ? msg('That level is still locked: finish the one before it first.')
          : msg('That level cannot be played: its file has problems.'),
        'error',
      );
  }

  map(choice: MapChoice): void {
    const session = this.session;
    if (!session) return;
    if (choice.kind === 'level') this.openLevel(choice.id);
    else if (choice.kind === 'free-lab') {
      this.host.closeRenderWindow();
      session.openFreeLab();
    } else {
      const current = session.engine.progress.current?.level;
      if (current) this.openLevel(current);
    }
  }

  progress(command: ProgressCommand): void {
    const session = this.session;
    if (!session) return;
    switch (command.kind) {
      case 'locale':
        session.setLocale(command.locale);
        // The levels' texts come in one language (level-catalog-browser.ts): the page starts
        // again in the new one, its progress saved.
        void chooseLocale(command.locale).then((locale) => {
          if (locale !== levelTextsLocale()) location.reload();
          else showLocaleProblem(document);
        });
        return;
      case 'palette':
        // Through the store, like the ray panel's switch: the session saves it with the progress.
        this.host.store.dispatch({ type: 'rays.changed', changes: { colorBlindPalette: command.colorBlind } });
        return;
      case 'export':
        return downloadText(session.exportText(), 'ray-tracer-quest-progress.json', 'application/json');
      case 'import':
        return this.imported(session, command.text, command.fileName);
      case 'reset': {
        const problem = session.reset();
        this.host.toast(
          problem ? msg(str`Your progress was not reset: ${saveProblemReason(problem)}.`) : msg('Your progress was reset. Start again from the level map.'),
          problem ? 'error' : 'info',
        );
        return;
      }
      case 'damaged-download': {
        const text = session.damagedSaves.text(command.key);
        const save = session.damagedSaves.all.find((entry) => entry.key === command.key);
        if (text === null || !save) return this.host.toast(msg('That damaged save is gone (deleted in another tab?).'), 'error');
        downloadText(text, damagedSaveFileName(save), 'application/json');
        // A held save may be written over now that the learner has it: saving goes on.
        session.damagedSaves.downloaded(command.key);
        session.flush();
        return this.changed();
      }
      case 'withdraw':
        session.stopSaving();
        return command.done(deleteAssignmentData(browserStorage(), session.progressKey));
      case 'damaged-restore':
        return this.restored(session, command.key);
      case 'damaged-delete':
        session.damagedSaves.delete(command.key);
        this.host.toast(msg('The damaged save was deleted.'));
        return this.changed();
    }
  }

  /** Why progress is not being saved now, with what to do (for the Menu), or ''. */
  get saveNote(): string {
    const problem = this.session?.saveProblem;
    return problem ? saveProblemText(problem) : '';
  }

  /** The survey's answers for the task column: as handed in this visit or read from storage. */
  get survey(): SurveySubmission | null {
    return this.session?.survey.submission ?? null;
  }

  /** The closing survey was handed in: kept with this session's progress, and said "saved" only when it was. */
  surveySubmitted(answers: SurveySubmission): void {
    const problem = this.session?.survey.submit(answers);
    if (problem === undefined) return;
    this.host.toast(
      problem
        ? msg(
            str`Thank you! Your answers could not be saved in the browser: ${saveProblemReason(problem)}. They are kept while this page is open: download your data below now for your teacher.`,
          )
        : msg('Thank you! Your answers are saved. Download your data below for your teacher.'),
      problem ? 'error' : 'info',
    );
    this.host.requestUpdate();
  }

  private imported(session: QuestSession, text: string, fileName: string): void {
    const result = session.importText(text);
    if (result.ok) {
      this.host.toast(msg(str`Progress imported from ${fileName}.`) + leftOut(result.repaired) + labCodeImportText(result.code));
    } else if (result.reason === 'unreadable') {
      this.host.toast(
        msg(str`${fileName} is not a progress file this app can read, so nothing changed:\n${result.errors.slice(0, 3).map(issueText).join('\n')}`),
        'error',
      );
    } else {
      this.host.toast(
        msg(str`${fileName} (${fileSize(text.length)}) was not imported: ${saveProblemReason(result.kind)}. Nothing changed: your progress is as it was.`),
        'error',
      );
    }
  }

  private restored(session: QuestSession, key: string): void {
    const result = session.restoreBackup(key);
    if (result.ok) {
      this.host.toast(msg('The damaged save is restored: what could be read of it is back in your progress.') + leftOut(result.repaired));
    } else if (result.reason === 'unreadable') {
      const reasons = result.errors.length > 0 ? ` (${shortList(result.errors.map(issueText), 2)})` : '';
      this.host.toast(msg(str`This version of the game cannot read that save${reasons}, so nothing changed. Download it to keep it.`), 'error');
    } else {
      this.host.toast(msg(str`The save was not restored: ${saveProblemReason(result.kind)}. Nothing changed.`), 'error');
    }
    this.changed();
  }

  /** A save problem is told when it starts (not at every change while it lasts), and so is its end. */
  private tellSaveProblem(): void {
    const problem = this.session?.saveProblem ?? null;
    if (problem === this.toldSaveProblem) return;
    const before = this.toldSaveProblem;
    this.toldSaveProblem = problem;
    const free =
      problem && this.session?.damagedSaves.all.some((save) => !save.held)
        ? ` ${msg('Deleting the damaged saves you have downloaded (Menu) frees space.')}`
        : '';
    const text = problem ? saveProblemText(problem) + free : before ? msg("Saved again: your progress is in the browser's storage.") : '';
    // At the start the toast is on the page only after the first render.
    if (text) void this.host.updateComplete.then(() => this.host.toast(text, problem ? 'error' : 'info'));
  }

  /** Puts the closing survey off (back to the lab), or opens it again. */
  putSurveyOff(later: boolean): void {
    this.surveyLater = later;
    this.host.requestUpdate();
  }

  dismissWelcome(): void {
    this.welcome = false;
    this.host.requestUpdate();
  }
}
