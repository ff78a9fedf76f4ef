// The path debugger (issue 42) in Chromium on a real pixel's paths: a vertex chosen from its
// list (the keyboard's way) or by a click on a drawn ray in the 3D view (the focus's
// chooseRay) moves the debugger there, reports the step and draws the lobe at a diffuse
// vertex; "show me" for a path-debugger step goes to the solution's vertex once the paths
// are traced.
import { afterEach, describe, expect, it } from 'vitest';
import { page, userEvent } from 'vitest/browser';
import { pathRayOf } from '../../src/debugger/path-goals.ts';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { labPaths } from '../../src/tracer/lab-paths.ts';
import type { RayFocus } from '../../src/view/ray-focus.ts';
import '../../src/ui/lab/debugger/rt-path-debugger.ts';
import { PATH_BALL_SCENE_FILE, pathBallScene } from '../support/path-ball-scene.ts';
import { sceneFrom } from '../support/test-scene.ts';
import { mount, unmountAll } from './mount.ts';

afterEach(unmountAll);

const paths = labPaths(pathBallScene(), 2, 2, 1);

async function debuggerOnPixel() {
  const focuses: (RayFocus | null)[] = [];
  const reports: LabAction[] = [];
  let traced!: () => void;
  const tracing = new Promise<void>((resolve) => (traced = resolve));
  const element = await mount('rt-path-debugger', {
    settings: sceneFrom(PATH_BALL_SCENE_FILE).settings,
    tracePaths: async () => {
      traced();
      return paths;
    },
    showFocus: (focus) => focuses.push(focus),
    report: (action) => reports.push(action),
  });
  /** Chooses the pixel; `atStart`: waits until the debugger stands at the first path's camera. */
  const traceNow = async (atStart = true) => {
    element.pixel = [2, 2];
    await tracing;
    if (atStart) await expect.poll(() => element.dataset.vertex).toBe('0');
  };
  return { element, focuses, reports, traceNow };
}

const steps = (reports: LabAction[]) => reports.flatMap((action) => (action.type === 'debugger.stepped' ? [action] : []));

describe('the path debugger’s chosen vertex', () => {
  it('goes to a vertex chosen from its list, reports the step and draws the lobe there at a diffuse bounce', async () => {
    const { element, focuses, reports, traceNow } = await debuggerOnPixel();
    await traceNow();
    const path = paths.paths[0]!;
    const diffuse = path.vertices.findIndex((vertex) => vertex.event === 'diffuse');
    expect(diffuse).toBeGreaterThan(0);
    const list = page.elementLocator(element.shadowRoot!.querySelector('select')!);
    await expect.element(list).toHaveAccessibleName(/Go to/);
    await userEvent.selectOptions(list, String(diffuse));
    await expect.poll(() => element.dataset.vertex).toBe(String(diffuse));
    expect(steps(reports).at(-1)).toEqual({ type: 'debugger.stepped', step: diffuse, of: path.vertices.length, ray: pathRayOf(path, diffuse) });
    expect(focuses.at(-1)?.lobe?.point).toEqual(path.vertices[diffuse]!.point);
  });

  it('goes to the vertex of a ray clicked in the 3D view, in whichever path it belongs to', async () => {
    const { element, focuses, reports, traceNow } = await debuggerOnPixel();
    await traceNow();
    element.onKeyDown(new KeyboardEvent('keydown', { key: 'End' }));
    const focus = focuses.at(-1)!;
    // Path 0's camera ray, clicked near its far end: the first vertex it reaches.
    const camera = focus.trace.rays[0]!;
    expect(focus.chooseRay?.(camera, camera.length * 0.9)).toBe(true);
    await expect.poll(() => [element.dataset.path, element.dataset.vertex]).toEqual(['0', '1']);
    expect(steps(reports).at(-1)?.ray).toEqual(pathRayOf(paths.paths[0]!, 1));
    // Another path's camera ray, near the camera: that path's start.
    const other = focus.trace.rays[2]!;
    expect(focuses.at(-1)!.chooseRay?.(other, 0.01)).toBe(true);
    await expect.poll(() => [element.dataset.path, element.dataset.vertex]).toEqual(['2', '0']);
  });
});

describe('“show me” for a path-debugger step', () => {
  it('goes to the solution’s vertex when the paths are traced, and reports it as a learner’s step', async () => {
    const { element, reports, traceNow } = await debuggerOnPixel();
    const path = paths.paths[1]!;
    const last = path.vertices.length - 1;
    const ray = pathRayOf(path, last)!;
    const earlier = paths.paths[0]!.vertices.findIndex((_, v) => JSON.stringify(pathRayOf(paths.paths[0]!, v)) === JSON.stringify(ray));
    element.perform({ type: 'debugger.stepped', step: last, of: path.vertices.length, ray });
    await traceNow(false);
    // The first path with that very ray: the solution's own unless path 0 has it too.
    const expected = earlier > 0 ? ['0', String(earlier)] : ['1', String(last)];
    await expect.poll(() => [element.dataset.path, element.dataset.vertex]).toEqual(expected);
    expect(steps(reports).at(-1)?.ray).toEqual(ray);
    expect(last).toBeGreaterThan(0);
  });
});
