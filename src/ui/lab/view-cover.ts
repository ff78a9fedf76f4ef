import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { previewBox } from './preview-place.ts';

/**
 * How much of the 3D view's bottom the panels laid over it cover (the pixel preview, the
 * open ray debugger), kept up to date as they open, close and change size: the view frames
 * what a task shows into the part above them (LabView.setCoveredBottom). An overlay counts
 * when it starts in the view's lower 70 %: the closed debugger's button at the top does not.
 */
export class ViewCoverController implements ReactiveController {
  private readonly observer = new ResizeObserver(() => this.measure());
  private watched: Element[] = [];

  constructor(
    host: ReactiveControllerHost,
    private readonly parts: () => { view: Element | null; overlays: Element[]; tell: (px: number) => void },
  ) {
    host.addController(this);
  }

  hostUpdated(): void {
    const { view, overlays } = this.parts();
    const now = view ? [view, ...overlays] : [];
    if (now.length !== this.watched.length || now.some((element, index) => element !== this.watched[index])) {
      this.observer.disconnect();
      for (const element of now) this.observer.observe(element);
      this.watched = now;
    }
    this.measure();
  }

  hostDisconnected(): void {
    this.observer.disconnect();
    this.watched = [];
  }

  private measure(): void {
    const { view, overlays, tell } = this.parts();
    if (!view) return;
    const box = view.getBoundingClientRect();
    tell(
      coveredBottom(
        box,
        overlays.map((overlay) => homeBox(overlay, box)),
      ),
    );
  }
}

/**
 * An overlay moved out of the way of the chosen pixel's rays (the pixel preview in the upper
 * right: preview-place.ts) counts at its home in the lower left: the framing keeps that
 * place free, so the preview can come back to it without covering what a task shows.
 */
function homeBox(overlay: Element, view: Box): Box {
  const box = overlay.getBoundingClientRect();
  if (!(overlay instanceof HTMLElement) || overlay.dataset.place !== 'top-right') return box;
  const home = previewBox('home', view, box);
  const left = view.left + home.left;
  const top = view.top + home.top;
  return { left, top, right: left + home.width, bottom: top + home.height, width: home.width, height: home.height };
}

type Box = Pick<DOMRectReadOnly, 'left' | 'top' | 'right' | 'bottom' | 'width' | 'height'>;

/** The height of the view's bottom that overlays starting in its lower 70 % cover (CSS px). */
export function coveredBottom(view: Box, overlays: Box[]): number {
  let covered = 0;
  for (const overlay of overlays) {
    const overlapsAcross = overlay.right > view.left && overlay.left < view.right && overlay.width > 0 && overlay.height > 0;
    if (!overlapsAcross || overlay.top < view.top + view.height * 0.3 || overlay.top >= view.bottom) continue;
    covered = Math.max(covered, view.bottom - overlay.top);
  }
  return covered;
}
