import { describe, expect, it } from 'vitest';
import { guideRect, itemPosition, viewPointOf, type GuideStage } from '../../../src/ui/lab/guide-targets.ts';

const scene: GuideStage['scene'] = {
  objects: [{ id: 'ball', position: [1, 2, 3] }],
  lights: [{ id: 'lamp', position: [4, 5, 6] }],
  camera: { position: [0, 1, 8] },
};

/** An element whose box is `box` (only what guideRect reads). */
const boxed = (left: number, top: number, width: number, height: number) =>
  ({ getBoundingClientRect: () => ({ left, top, width, height, right: left + width, bottom: top + height }) }) as unknown as Element;

function stage(elements: Record<string, Element[]>, project: GuideStage['project'] = () => ({ x: 100, y: 50 })): GuideStage {
  return { elements: (id) => elements[id] ?? [], project, canvas: boxed(10, 20, 800, 600) as unknown as HTMLElement, scene };
}

describe('guide target names → places on the page', () => {
  it('rings the elements that carry the id, around all of them (both pixel sliders)', () => {
    const rect = guideRect('tracer.pixels', stage({ 'tracer.pixels': [boxed(0, 100, 200, 30), boxed(0, 140, 200, 30)] }));
    expect(rect).toEqual({ left: 0, top: 100, width: 200, height: 70 });
  });

  it('leaves out elements that take no room (hidden ones)', () => {
    const rect = guideRect('object.color', stage({ 'object.color': [boxed(0, 0, 0, 0), boxed(5, 6, 7, 8)] }));
    expect(rect).toEqual({ left: 5, top: 6, width: 7, height: 8 });
  });

  it('rings an item of the 3D view at its projected point, and the camera for its screen without the preview', () => {
    const seen: number[][] = [];
    const project: GuideStage['project'] = (point) => (seen.push([...point]), { x: 100, y: 50 });
    expect(guideRect('view.item:ball', stage({}, project))).toEqual({ left: 10 + 100 - 32, top: 20 + 50 - 32, width: 64, height: 64 });
    guideRect('screen.pixel:3,2', stage({}, project));
    guideRect('screen.grid', stage({}, project));
    expect(seen).toEqual([
      [1, 2, 3],
      [0, 1, 8],
      [0, 1, 8],
    ]);
  });

  it("prefers the flat preview's pixel to the camera when the preview is on the page", () => {
    const rect = guideRect('screen.pixel:3,2', stage({ 'screen.pixel:3,2': [boxed(40, 500, 24, 24)] }));
    expect(rect).toEqual({ left: 40, top: 500, width: 24, height: 24 });
  });

  it('rings the Render image button for a control of the closed render window', () => {
    const header = boxed(900, 8, 120, 32);
    expect(guideRect('render.start', stage({ 'render.open': [header] }))).toEqual({ left: 900, top: 8, width: 120, height: 32 });
    expect(guideRect('render.start', stage({ 'render.open': [header], 'render.start': [boxed(300, 100, 80, 32)] }))).toEqual({
      left: 300,
      top: 100,
      width: 80,
      height: 32,
    });
  });

  it('rings the button that shows the panels for a control of the hidden panels (a small screen showing the tasks)', () => {
    const button = boxed(400, 44, 170, 32);
    const hidden = { 'object.color': [boxed(0, 0, 0, 0)] };
    expect(guideRect('object.color', { ...stage(hidden), panelsButton: button })).toEqual({ left: 400, top: 44, width: 170, height: 32 });
    // Shown panels, a wide screen (the button takes no room), or a control not on the page at all: no stand-in.
    expect(guideRect('object.color', { ...stage({ 'object.color': [boxed(5, 6, 7, 8)] }), panelsButton: button })).toEqual({
      left: 5,
      top: 6,
      width: 7,
      height: 8,
    });
    expect(guideRect('object.color', { ...stage(hidden), panelsButton: boxed(0, 0, 0, 0) })).toBeNull();
    expect(guideRect('tracer.supersampling', { ...stage({}), panelsButton: button })).toBeNull();
  });

  it('has no ring for a control that is not on the page, or a point behind the eye', () => {
    expect(guideRect('tracer.supersampling', stage({}))).toBeNull();
    expect(
      guideRect(
        'view.item:ball',
        stage({}, () => null),
      ),
    ).toBeNull();
    expect(guideRect('view.item:nothing', stage({}))).toBeNull();
  });

  it('reads items and pixels, and refuses what is not a target', () => {
    expect(viewPointOf('view.item:lamp', scene)).toEqual([4, 5, 6]);
    expect(viewPointOf('screen.pixel:3,2', scene)).toEqual([0, 1, 8]);
    expect(viewPointOf('tracer.nonsense', scene)).toBeUndefined();
    expect(viewPointOf('view.item:', scene)).toBeUndefined();
    expect(viewPointOf('tracer.supersampling', scene)).toBeUndefined();
  });

  it('finds the position of an object or a light', () => {
    expect(itemPosition(scene, 'ball')).toEqual([1, 2, 3]);
    expect(itemPosition(scene, 'lamp')).toEqual([4, 5, 6]);
    expect(itemPosition(scene, 'nothing')).toBeUndefined();
  });
});
