import type { LabState } from '../lab-state/lab-state.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import { LAB_PATH_COUNT } from '../tracer/lab-path-count.ts';
import type { LabPaths } from '../tracer/lab-paths.ts';
import type { RayFocus } from '../view/ray-focus.ts';

/**
 * A chosen pixel's sample paths in path mode, drawn with the ray debugger closed too (issue
 * 42): the screen's rays are Whitted trees, which say nothing about the paths the picture
 * averages. Traces the pixel's first paths again when the pixel or the screen (a changed
 * scene) changes, and hands the view every path whole (path-focus.ts allPathsFocus); the
 * debugger's own focus, while open, is drawn instead (lab-services.ts).
 */
export class PathPixelFocus {
  private tracedFor: { pixel: readonly [number, number]; rays: ScreenRays } | null = null;
  private request = 0;

  constructor(
    private readonly tracePaths: (x: number, y: number, keep: number) => Promise<LabPaths>,
    private readonly show: (focus: RayFocus | null) => void,
  ) {}

  /** Follows the state and the latest screen of rays. */
  follow(state: LabState, rays: ScreenRays | null): void {
    const { integrator, russianRoulette } = state.scene.settings;
    const pixel = integrator === 'path' ? state.selectedPixel : null;
    if (!pixel || !rays) {
      if (this.tracedFor) this.stop();
      return;
    }
    const traced = this.tracedFor;
    if (traced && traced.pixel === pixel && traced.rays === rays) return;
    this.tracedFor = { pixel, rays };
    const request = ++this.request;
    // The drawing code loads with the first chosen pixel in path mode, not with the first screen.
    Promise.all([this.tracePaths(pixel[0], pixel[1], LAB_PATH_COUNT), import('../debugger/path-steps.ts'), import('../view/path-focus.ts')]).then(
      ([paths, { pathRows }, { allPathsFocus, pathTrees }]) => {
        if (request !== this.request) return;
        // The throughput each segment carries, as the debugger's rows compute it.
        const carried = paths.paths.map((path) => pathRows(path, { russianRoulette }).map((row) => row.throughput));
        this.show(allPathsFocus(pathTrees(paths, carried)));
      },
      () => {
        if (request === this.request) this.show(null);
      },
    );
  }

  private stop(): void {
    this.tracedFor = null;
    this.request++;
    this.show(null);
  }
}
