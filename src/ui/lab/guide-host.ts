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

/** What a host sends as it connects: itself, and a place for the registry that keeps it to leave how it is forgotten. */
export interface GuideHostAnnouncement {
  readonly host: GuideHost;
  /** Set by the registry that keeps the host; called when the host leaves the page. */
  forget?: () => void;
}

type HostElement = ReactiveControllerHost & HTMLElement & { readonly renderRoot: ParentNode };

/** An element that can be opened to show what it holds (rt-panel-section's `open`). */
interface Openable extends HTMLElement {
  open: boolean;
}

/**
 * Makes a lit element a guide host over its own render root: it announces itself to the
 * registry around it as it connects, and leaves it as it disconnects.
 */
export class GuideHostController implements ReactiveController, GuideHost {
  /** How the registry that keeps this host forgets it, while one does. */
  private forget: (() => void) | undefined;

  constructor(readonly element: HostElement) {
    element.addController(this);
  }

  hostConnected(): void {
    const announcement: GuideHostAnnouncement = { host: this };
    this.element.dispatchEvent(new CustomEvent<GuideHostAnnouncement>(GUIDE_HOST_EVENT, { detail: announcement, bubbles: true, composed: true }));
    this.forget = announcement.forget;
  }

  hostDisconnected(): void {
    this.forget?.();
    this.forget = undefined;
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
 * The hosts on the page inside one element (the lab): they announce themselves as they
 * connect and are forgotten as they disconnect. A host kept after it left would keep its
 * whole element alive, and with it everything it rendered: each visit to the level map
 * replaces the lab's panels, and kept their old ones, about 2,000 DOM nodes and 0.32 MB
 * a visit.
 */
export class GuideRegistry {
  private readonly hosts = new Set<GuideHost>();

  constructor(root: HTMLElement) {
    root.addEventListener(GUIDE_HOST_EVENT, (event) => {
      event.stopPropagation();
      const announcement = (event as CustomEvent<GuideHostAnnouncement>).detail;
      this.hosts.add(announcement.host);
      announcement.forget = () => this.hosts.delete(announcement.host);
    });
  }

  /** How many hosts it keeps (for tests). */
  get size(): number {
    return this.hosts.size;
  }

  /** Every element on the page that carries `id`. */
  elements(id: string): Element[] {
    return [...this.hosts].flatMap((host) => host.elements(id));
  }

  reveal(id: string): void {
    [...this.hosts].find((host) => host.elements(id).length > 0)?.reveal(id);
  }
}

/** An id inside a quoted CSS attribute value (ids are kebab-case; quotes and backslashes are escaped anyway). */
function cssString(text: string): string {
  return text.replace(/["\\]/g, '\\$&');
}
