import { ContextProvider } from '@lit/context';
import type { ReactiveControllerHost } from 'lit';
import type { LabServices } from '../../app/lab-services.ts';
import type { Scene } from '../../scene/scene.ts';
import type { LabView } from '../../view/lab-view.ts';
import { challengePicturesContext } from '../game/challenge-pictures.ts';
import { codeLabHostContext } from '../game/code-lab/code-lab-host.ts';
import { quizPicturesContext } from '../game/quiz-pictures.ts';
import { ChallengeReferee } from './challenge-referee.ts';
import { codeLabReporter } from './code-lab-reporter.ts';
import { quizPictureDrawer } from './quiz-picture-drawer.ts';

/**
 * The lab's pictures for the task column, rendered by its services: a picture prediction's
 * choices, and a challenge's referee, which follows the store while the lab is on the page
 * (a lab back on the page has new services, so it follows their store), and where a code
 * lab's runs are reported.
 */
export function providePictures(
  host: ReactiveControllerHost & HTMLElement,
  lab: () => { services: LabServices; levelScene: Scene | undefined; view: LabView | null },
): void {
  const services = () => lab().services;
  new ContextProvider(host, { context: quizPicturesContext, initialValue: quizPictureDrawer(services) });
  const referee = new ChallengeReferee(services, () => lab().levelScene);
  new ContextProvider(host, { context: challengePicturesContext, initialValue: referee });
  new ContextProvider(host, {
    context: codeLabHostContext,
    initialValue: codeLabReporter(
      () => services().store,
      () => lab().view,
      () => lab().levelScene,
    ),
  });
  let stop: (() => void) | null = null;
  host.addController({
    hostConnected: () => (stop = referee.attach(services().store)),
    hostDisconnected: () => {
      stop?.();
      stop = null;
    },
  });
}
