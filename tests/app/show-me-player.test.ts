import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { kindOfAction, playShowMe, showMeSteps, type ShowMeStage } from '../../src/app/show-me-player.ts';

describe('show me: facts are performed through the UI, state changes dispatched', () => {
  it('tells facts from state changes', () => {
    expect(kindOfAction({ type: 'view.orbited' })).toBe('fact');
    expect(kindOfAction({ type: 'render.finished', ms: 3 })).toBe('fact');
    expect(kindOfAction({ type: 'panel.opened', panel: 'render' })).toBe('fact');
    expect(kindOfAction({ type: 'settings.changed', changes: { supersampling: 2 } })).toBe('state');
    expect(kindOfAction({ type: 'selection.changed', selection: null })).toBe('state');
  });

  it('turns a render solution into opening the window and one real render', () => {
    const actions: LabAction[] = [{ type: 'panel.opened', panel: 'render' }, { type: 'render.started' }, { type: 'render.finished', ms: 800 }];
    expect(showMeSteps(actions)).toEqual([{ kind: 'open-render' }, { kind: 'render' }]);
  });

  it('keeps the order of mixed steps', () => {
    const select: LabAction = { type: 'selection.changed', selection: { kind: 'object', id: 'ball' } };
    expect(showMeSteps([select, { type: 'view.orbited' }, { type: 'view.flew-to-camera' }, { type: 'panel.opened', panel: 'rays' }])).toEqual([
      { kind: 'dispatch', action: select },
      { kind: 'orbit' },
      { kind: 'fly-to-camera' },
      { kind: 'open-panel', panel: 'rays' },
    ]);
  });

  it('has the ray debugger perform what it reports: go to a ray, click a term', () => {
    const stepped: LabAction = {
      type: 'debugger.stepped',
      step: 3,
      of: 9,
      ray: { type: 'shadow', depth: 0, hit: true, objectId: 'ball', lightId: 'lamp', from: 'floor' },
    };
    const clicked: LabAction = { type: 'debugger.term-clicked', term: 'specular', lightId: 'lamp' };
    expect(kindOfAction(stepped)).toBe('fact');
    expect(showMeSteps([{ type: 'pixel.selected', pixel: [2, 2] }, stepped, clicked])).toEqual([
      { kind: 'dispatch', action: { type: 'pixel.selected', pixel: [2, 2] } },
      { kind: 'debug', action: stepped },
      { kind: 'debug', action: clicked },
    ]);
  });
});

describe('playing the steps', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  const recorder = () => {
    const done: string[] = [];
    const stage: ShowMeStage = {
      dispatch: (action) => done.push(action.type),
      orbit: () => done.push('orbit'),
      pan: () => done.push('pan'),
      zoom: () => done.push('zoom'),
      flyToCamera: () => done.push('fly'),
      openRender: () => done.push('open-render'),
      render: () => done.push('render'),
      openPanel: (panel) => done.push(`panel ${panel}`),
      debug: (action) => done.push(`debug ${action.type}`),
    };
    return { done, stage };
  };

  it('performs one step per interval, visibly, and says when it is done', () => {
    const { done, stage } = recorder();
    const finished = vi.fn();
    playShowMe([{ kind: 'orbit' }, { kind: 'dispatch', action: { type: 'pixel.deselected' } }], stage, 600, finished);
    expect(done).toEqual([]);
    vi.advanceTimersByTime(600);
    expect(done).toEqual(['orbit']);
    vi.advanceTimersByTime(600);
    expect(done).toEqual(['orbit', 'pixel.deselected']);
    vi.advanceTimersByTime(600);
    expect(finished).toHaveBeenCalledOnce();
  });

  it('stops when asked', () => {
    const { done, stage } = recorder();
    const stop = playShowMe([{ kind: 'zoom' }, { kind: 'pan' }], stage, 600);
    vi.advanceTimersByTime(600);
    stop();
    vi.advanceTimersByTime(5000);
    expect(done).toEqual(['zoom']);
  });
});
