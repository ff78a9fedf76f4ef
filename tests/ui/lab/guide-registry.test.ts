import { describe, expect, it } from 'vitest';
import { GuideHostController, GuideRegistry } from '../../../src/ui/lab/guide-host.ts';

/**
 * The lab's guide registry and the hosts that announce themselves to it (issue 38, item 5:
 * every visit to the level map replaced the lab's panels, and the registry kept the old ones
 * alive until a "Show me where" happened to ask it). No DOM here: the lab is an event target,
 * and a host's events reach it as they would by bubbling.
 */

/** A lit element as the controller sees it: it takes controllers, dispatches to `lab` and renders `marked`. */
function fakeHost(lab: EventTarget, marked: Element[]) {
  const host = {
    controllers: [] as GuideHostController[],
    addController(controller: GuideHostController) {
      host.controllers.push(controller);
    },
    dispatchEvent: (event: Event) => lab.dispatchEvent(event),
    renderRoot: { querySelectorAll: () => marked },
  };
  return host;
}

const marker = (name: string) => ({ name, parentElement: null }) as unknown as Element;

describe('GuideRegistry', () => {
  it('keeps a host while it is on the page and forgets it when it leaves', () => {
    const lab = new EventTarget();
    const registry = new GuideRegistry(lab as HTMLElement);
    const slider = marker('tracer.supersampling');
    const host = fakeHost(lab, [slider]);
    const controller = new GuideHostController(host as unknown as ConstructorParameters<typeof GuideHostController>[0]);
    expect(host.controllers).toEqual([controller]);

    controller.hostConnected();
    expect(registry.size).toBe(1);
    expect(registry.elements('tracer.supersampling')).toEqual([slider]);

    // The panel leaves the page (the level map replaced the lab's panels): nothing holds it any more.
    controller.hostDisconnected();
    expect(registry.size).toBe(0);
    expect(registry.elements('tracer.supersampling')).toEqual([]);

    // Back on the page, it is found again.
    controller.hostConnected();
    expect(registry.elements('tracer.supersampling')).toEqual([slider]);
  });

  it('forgets each of many hosts that came and went, keeping the ones still there', () => {
    const lab = new EventTarget();
    const registry = new GuideRegistry(lab as HTMLElement);
    const make = () => new GuideHostController(fakeHost(lab, [marker('panel')]) as unknown as ConstructorParameters<typeof GuideHostController>[0]);
    const staying = make();
    staying.hostConnected();
    for (let visit = 0; visit < 40; visit++) {
      const panels = [make(), make(), make()];
      for (const panel of panels) panel.hostConnected();
      for (const panel of panels) panel.hostDisconnected();
    }
    expect(registry.size).toBe(1);
    expect(registry.elements('panel')).toHaveLength(1);
  });

  it('lets a host with no registry around it connect and leave', () => {
    const nowhere = new EventTarget();
    const controller = new GuideHostController(fakeHost(nowhere, []) as unknown as ConstructorParameters<typeof GuideHostController>[0]);
    controller.hostConnected();
    expect(() => controller.hostDisconnected()).not.toThrow();
  });
});
