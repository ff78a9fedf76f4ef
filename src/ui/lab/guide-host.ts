import type { ReactiveController, ReactiveControllerHost } from 'lit';

/**
 * An element that marks some of its own rendered controls with guide ids (the levels'
 * control names, `data-guide="tracer.supersampling"`; several ids are separated by spaces).
 * The lab asks hosts for a control by its id; nobody else looks inside them.
 */
export interface GuideHost {
  readonly element: HTMLElement;
  /** The host's rendered elements that carry `id`. */
  elements(id: string): Element[];
  /** Opens what hides the first of them (a collapsed section) and scrolls it into view. */
  reveal(id: string): void;
}

/** Sent (bubbling, composed) by a host when it connects; the lab's GuideRegistry keeps it. */
export const GUIDE_HOST_EVENT = 'guide-host';

type HostElement = ReactiveControllerHost & HTMLElement & { readonly renderRoot: ParentNode };

/** An element that can be opened to show what it holds (rt-panel-section's `open`). */
interface Openable extends HTMLElement {
  open: boolean;
}

/** Makes a lit element a guide host over its own render root. */
export class GuideHostController implements ReactiveController, GuideHost {
  constructor(readonly element: HostElement) {
    element.addController(this);
  }

  hostConnected(): void {
    this.element.dispatchEvent(new CustomEvent<GuideHost>(GUIDE_HOST_EVENT, { detail: this, bubbles: true, composed: true }));
  }

  elements(id: string): Element[] {
    return [...this.element.renderRoot.querySelectorAll(`[data-guide~="${cssString(id)}"]`)];
  }

  reveal(id: string): void {
    const [first] = this.elements(id);
    if (!first) return;
    // The control sits in a section of this host's own template: open the sections around it.
    for (let node = first.parentElement; node; node = node.parentElement) {
      if (node.localName === 'rt-panel-section' && !(node as Openable).open) (node as Openable).open = true;
    }
    first.scrollIntoView({ block: 'nearest', inline: 'nearest' });
  }
}

/**
 * The hosts inside one element (the lab): they announce themselves as they connect, and a
 * host that has left the page is forgotten when next asked.
 */
export class GuideRegistry {
  private readonly hosts = new Set<GuideHost>();

  constructor(root: HTMLElement) {
    root.addEventListener(GUIDE_HOST_EVENT, (event) => {
      event.stopPropagation();
      this.hosts.add((event as CustomEvent<GuideHost>).detail);
    });
  }

  /** Every connected element on the page that carries `id`. */
  elements(id: string): Element[] {
    return this.connected().flatMap((host) => host.elements(id));
  }

  reveal(id: string): void {
    this.connected().find((host) => host.elements(id).length > 0)?.reveal(id);
  }

  private connected(): GuideHost[] {
    for (const host of this.hosts) if (!host.element.isConnected) this.hosts.delete(host);
    return [...this.hosts];
  }
}

/** An id inside a quoted CSS attribute value (ids are kebab-case; quotes and backslashes are escaped anyway). */
function cssString(text: string): string {
  return text.replace(/["\\]/g, '\\$&');
}
