import { msg, str } from '@lit/localize';
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { levelTextsLocale, loadBrowserCatalog } from '../../app/level-catalog-browser.ts';
import { QuestSession } from '../../app/quest-session.ts';
import type { ShowMeStage } from '../../app/show-me-player.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import type { SurveySubmission } from '../../classroom/survey-answers.ts';
import { SurveyStore } from '../../classroom/survey-store.ts';
import { chooseLocale, currentLocale } from '../../i18n/locale.ts';
import { issueText } from '../../i18n/issue-text.ts';
import { progressProblemText } from '../../i18n/progress-problem-text.ts';
import type { Store } from '../../lab-state/store.ts';
import { MemoryStorage, type KeyValueStorage } from '../../quest/progress-store.ts';
import type { Scene } from '../../scene/scene.ts';
import { downloadText } from '../../util/download-file.ts';
import type { QuestCommand } from '../game/quest-command.ts';
import type { MapChoice } from '../game/rt-level-map.ts';
import type { ProgressCommand } from '../game/rt-progress-menu.ts';

/** The address fragment that opens the free lab instead of the game. */
export const FREE_LAB_HASH = '#free-lab';


/** localStorage, or a Map for this visit when the browser blocks it (the session then says progress is not kept). */
function browserStorage(): KeyValueStorage {
  try {
    return localStorage;
  } catch {
    return new MemoryStorage();
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
  /** The learner's survey answers in this session's progress (read once per session), or null before they hand it in. */
  survey: SurveySubmission | null = null;
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
    const catalog = loadBrowserCatalog();
    const storage = browserStorage();
    const session = new QuestSession({ store: this.host.store, catalog, storage, assignment: this.host.assignment });
    this.session = session;
    // The level texts speak the app's language (an address's ?lang= or the menu's choice may differ from the saved one).
    if (session.locale !== currentLocale()) session.setLocale(currentLocale());
    this.cleanup.push(
      session.subscribe(() => this.changed()),
      session.attach(document),
      () => session.dispose(),
    );
    const problems = [session.problem && progressProblemText(session.problem), catalog.errors.length > 0 ? msg(str`The level list could not be read: ${catalog.errors.map(issueText).join('; ')}`) : undefined];
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
    this.survey = new SurveyStore(storage, session.progressKey).load();
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
    if (this.session && this.session.mode.kind !== 'free-lab' && location.hash === FREE_LAB_HASH) history.replaceState(history.state, '', location.pathname + location.search);
    if (this.welcomeDue && this.session?.mode.kind === 'level') {
      this.welcomeDue = false;
      this.welcome = true;
    }
    const error = this.session?.saveError;
    if (error) this.host.toast(error, 'error');
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
    if (opened && !opened.ok) this.host.toast(opened.reason === 'locked' ? msg('That level is still locked: finish the one before it first.') : msg('That level cannot be played: its file has problems.'), 'error');
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
        });
        return;
      case 'palette':
        // Through the store, like the ray panel's switch: the session saves it with the progress.
        this.host.store.dispatch({ type: 'rays.changed', changes: { colorBlindPalette: command.colorBlind } });
        return;
      case 'export':
        return downloadText(session.exportText(), 'ray-tracer-quest-progress.json', 'application/json');
      case 'import': {
        const imported = session.importText(command.text);
        if (imported.ok) this.host.toast(msg(str`Progress imported from ${command.fileName}.`));
        else this.host.toast(msg(str`${command.fileName} is not a progress file this app can read, so nothing changed:\n${imported.errors.slice(0, 3).map(issueText).join('\n')}`), 'error');
        return;
      }
      case 'reset':
        session.reset();
        this.host.toast(msg('Your progress was reset. Start again from the level map.'));
        return;
    }
  }

  /** The closing survey was handed in: kept with this session's progress. */
  surveySubmitted(answers: SurveySubmission): void {
    const session = this.session;
    if (!session) return;
    new SurveyStore(browserStorage(), session.progressKey).save(answers);
    this.survey = answers;
    this.host.toast(msg('Thank you! Your answers are saved. Download your data below for your teacher.'));
    this.host.requestUpdate();
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
