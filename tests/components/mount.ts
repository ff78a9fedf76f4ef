/**
 * Mounting a custom element for a component test: created by its tag, given its properties
 * (as a panel sets them), added to the page and rendered.
 */
import type { LitElement } from 'lit';
import type { Store } from '../../src/lab-state/store.ts';
import { GuideRegistry } from '../../src/ui/lab/guide-host.ts';

const mounted: Element[] = [];

export async function mount<Tag extends keyof HTMLElementTagNameMap>(
  tag: Tag,
  properties: Partial<HTMLElementTagNameMap[Tag]> = {},
): Promise<HTMLElementTagNameMap[Tag]> {
  const element = document.createElement(tag);
  Object.assign(element, properties);
  document.body.append(element);
  mounted.push(element);
  await (element as unknown as LitElement).updateComplete;
  return element;
}

export function unmountAll(): void {
  for (const element of mounted.splice(0)) element.remove();
}

/** The details of the `type` events an element fires, in order. */
export function record<T>(element: EventTarget, type: string): T[] {
  const details: T[] = [];
  element.addEventListener(type, (event) => details.push((event as CustomEvent<T>).detail));
  return details;
}

/**
 * A lab panel on a store, inside an element that keeps its guide hosts as the lab does
 * (GuideRegistry): the test finds controls by their guide ids, as the hint ring does.
 */
export async function mountPanel<Tag extends keyof HTMLElementTagNameMap>(
  tag: Tag,
  store: Store,
  properties: Partial<HTMLElementTagNameMap[Tag]> = {},
): Promise<{ panel: HTMLElementTagNameMap[Tag]; guides: GuideRegistry }> {
  const lab = document.createElement('div');
  const guides = new GuideRegistry(lab);
  document.body.append(lab);
  mounted.push(lab);
  const panel = document.createElement(tag);
  Object.assign(panel, { store, ...properties });
  lab.append(panel);
  await (panel as unknown as LitElement).updateComplete;
  return { panel, guides };
}
