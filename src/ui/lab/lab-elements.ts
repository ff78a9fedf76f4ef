import type { UiPanel } from '../../quest/lab-controls.ts';
import { LazyModule } from '../../util/lazy-module.ts';
/**
 * Registers every element the lab's template uses (imported for their side effect: each
 * module defines its custom element), but those of ON_DEMAND_PANELS.
 */
import '../game/rt-participant-dialog.ts';
import '../game/rt-level-map.ts';
import '../game/rt-progress-menu.ts';
import '../game/rt-quest-panel.ts';
import '../game/rt-score.ts';
import '../controls/rt-theme-toggle.ts';
import '../controls/rt-load-problem.ts';
import '../controls/rt-toast.ts';
import './panels/rt-file-panel.ts';
import './panels/rt-light-panel.ts';
import './panels/rt-object-panel.ts';
import './panels/rt-ray-legend.ts';
import './panels/rt-ray-panel.ts';
import './panels/rt-scene-list.ts';
import './panels/rt-tracer-panel.ts';
import './rt-guide-ring.ts';
import './rt-scene-view.ts';
import './rt-screen-preview.ts';

/**
 * Panels only some levels show, loaded when a level first shows them (the element upgrades
 * then): the BVH panel builds the tracer's scene on the page, with three.js and
 * three-mesh-bvh, which a student's first load can do without; the ray debugger is opened
 * only after a pixel is chosen, so it comes after the first screen. A panel whose code cannot be
 * loaded is replaced by a message with a Reload button, after a few tries.
 */
export const ON_DEMAND_PANELS: Partial<Record<UiPanel, LazyModule<unknown>>> = {
  bvh: new LazyModule(() => import('./panels/rt-bvh-panel.ts')),
  debugger: new LazyModule(() => import('./debugger/rt-ray-debugger.ts')),
};

/**
 * The render window: closed on the first screen, so its code (the tiled render's painting,
 * the estimates, saving the picture) loads right after it, tried again like the on-demand
 * panels; Render opens it at once and it upgrades when its code is there. One that cannot be
 * loaded is said over the 3D view with a Reload button (lab-load-problem.ts).
 */
export const RENDER_WINDOW = new LazyModule(() => import('./render-window/rt-render-window.ts'));

/**
 * Runs `then` once the render window's code is there (Render may be clicked, or a "show me"
 * render asked, before it is); a load that failed makes `host` render again, to say so.
 */
export function withRenderWindow(host: { requestUpdate(): void }, then: () => unknown = () => undefined): void {
  RENDER_WINDOW.load().then(then, () => host.requestUpdate());
}

/**
 * Parts the first screen never shows: the closing survey, the concept test, the end of an
 * assignment, the Menu's hand-in buttons, withdrawal and line about the offline copy, the
 * tooltip of a ray pointed at in the 3D view (whose code loads after the first screen too),
 * and the render window's side-by-side comparison. They load once the lab is on
 * the page, and the lab renders again as each is defined (the survey waits for its element:
 * survey-page.ts); one that cannot be loaded is said in the console and left out.
 */
const AFTER_FIRST_SCREEN = [
  () => import('../classroom/rt-survey-page.ts'),
  () => import('../classroom/rt-concept-test.ts'),
  () => import('../game/rt-withdraw.ts'),
  () => import('../controls/rt-offline-status.ts'),
  () => import('./rt-ray-tooltip.ts'),
  () => import('../game/rt-assignment-done.ts'),
  () => import('../classroom/rt-export-menu.ts'),
  () => import('./render-window/rt-image-compare.ts'),
];

export function loadAfterFirstScreen(host: { requestUpdate(): void }): void {
  setTimeout(() => {
    RENDER_WINDOW.load().then(
      () => host.requestUpdate(),
      () => host.requestUpdate(),
    );
    for (const load of AFTER_FIRST_SCREEN)
      load().then(
        () => host.requestUpdate(),
        (error: unknown) => console.warn('A part of the lab could not be loaded', error),
      );
  });
}
