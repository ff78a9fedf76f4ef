import { ContextConsumer, createContext } from '@lit/context';
import type { ReactiveControllerHost } from 'lit';
import type { Store } from '../../lab-state/store.ts';

/**
 * The lab's one store, provided by rt-lab to every element inside it (panels, the 3D view,
 * the render window) instead of being handed down property by property.
 */
export const storeContext = createContext<Store | undefined>(Symbol('lab-store'));

/**
 * Takes the store from the nearest provider and gives it to `use` (again if the provider's
 * store changes). An element that was handed a `store` property directly keeps that one.
 */
export function consumeStore(
  host: ReactiveControllerHost & HTMLElement,
  use: (store: Store | undefined) => void,
): ContextConsumer<typeof storeContext, typeof host> {
  return new ContextConsumer(host, { context: storeContext, subscribe: true, callback: use });
}
