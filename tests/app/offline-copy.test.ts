import { expect, test } from 'vitest';
import { OfflineCopy, type OfflineCopyState } from '../../src/app/offline-copy.ts';

// The offline copy's state as the Menu shows it, from a service worker's life as browsers
// report it: a registration whose workers move installing → installed → activating →
// activated, or turn redundant when storing the build's files fails.

class FakeWorker extends EventTarget {
  constructor(public state: ServiceWorkerState) {
    super();
  }
  /** Moves to `state` and tells the listeners, as a browser does. */
  become(state: ServiceWorkerState): void {
    this.state = state;
    this.dispatchEvent(new Event('statechange'));
  }
}

class FakeRegistration extends EventTarget {
  installing: FakeWorker | null = null;
  waiting: FakeWorker | null = null;
  active: FakeWorker | null = null;
  /** A new worker of a newer build starts installing. */
  found(worker: FakeWorker): void {
    this.installing = worker;
    this.dispatchEvent(new Event('updatefound'));
  }
}

/** An OfflineCopy started against a container that answers `register` with `registration`, and every state it went through. */
async function started(registration: FakeRegistration) {
  const copy = new OfflineCopy();
  const seen: OfflineCopyState[] = [];
  copy.subscribe((state) => seen.push(state));
  const serviceWorker = { register: async () => registration as unknown as ServiceWorkerRegistration };
  await copy.start({ protocol: 'https:', serviceWorker });
  return { copy, seen };
}

test('a first visit is storing until the worker is active, then the app works offline', async () => {
  const registration = new FakeRegistration();
  const worker = new FakeWorker('installing');
  registration.installing = worker;
  const { copy } = await started(registration);
  expect(copy.state).toEqual({ kind: 'storing' });

  worker.become('installed');
  registration.installing = null;
  registration.waiting = worker;
  expect(copy.state).toEqual({ kind: 'storing' });
  registration.waiting = null;
  registration.active = worker;
  worker.become('activating');
  expect(copy.state).toEqual({ kind: 'stored', newVersionWaiting: false });
  worker.become('activated');
  expect(copy.state).toEqual({ kind: 'stored', newVersionWaiting: false });
});

test('a worker that cannot store the files (too little storage) means the app is not stored', async () => {
  const registration = new FakeRegistration();
  const worker = new FakeWorker('installing');
  registration.installing = worker;
  const { copy } = await started(registration);
  // The browser marks the worker redundant before it clears the registration's slot.
  worker.become('redundant');
  expect(copy.state).toEqual({ kind: 'not-stored', reason: 'failed', detail: '' });
  registration.installing = null;
  worker.become('redundant');
  expect(copy.state).toEqual({ kind: 'not-stored', reason: 'failed', detail: '' });
});

test('a newer build installs beside the stored one and is said to wait', async () => {
  const registration = new FakeRegistration();
  registration.active = new FakeWorker('activated');
  const { copy } = await started(registration);
  expect(copy.state).toEqual({ kind: 'stored', newVersionWaiting: false });

  const newer = new FakeWorker('installing');
  registration.found(newer);
  expect(copy.state).toEqual({ kind: 'stored', newVersionWaiting: false });
  registration.installing = null;
  registration.waiting = newer;
  newer.become('installed');
  expect(copy.state).toEqual({ kind: 'stored', newVersionWaiting: true });
});

test('a newer build that cannot be stored leaves the stored one working', async () => {
  const registration = new FakeRegistration();
  registration.active = new FakeWorker('activated');
  const { copy, seen } = await started(registration);
  const newer = new FakeWorker('installing');
  registration.found(newer);
  newer.become('redundant');
  registration.installing = null;
  expect(copy.state).toEqual({ kind: 'stored', newVersionWaiting: false });
  expect(seen.every((state) => state.kind === 'stored')).toBe(true);
});

test('no service workers, a refused registration, or a page from disk each say why', async () => {
  const without = new OfflineCopy();
  await without.start({ protocol: 'https:', serviceWorker: undefined });
  expect(without.state).toEqual({ kind: 'not-stored', reason: 'unsupported', detail: '' });

  const refused = new OfflineCopy();
  await refused.start({
    protocol: 'http:',
    serviceWorker: {
      register: async () => {
        throw new DOMException('Failed to register a ServiceWorker: The document is in an invalid state.', 'SecurityError');
      },
    },
  });
  expect(refused.state).toEqual({ kind: 'not-stored', reason: 'refused', detail: 'Failed to register a ServiceWorker: The document is in an invalid state.' });

  // A browser that blocks workers may answer without a registration (Playwright does).
  const blocked = new OfflineCopy();
  await blocked.start({ protocol: 'https:', serviceWorker: { register: async () => undefined as unknown as ServiceWorkerRegistration } });
  expect(blocked.state).toEqual({ kind: 'not-stored', reason: 'refused', detail: '' });

  const fromDisk = new OfflineCopy();
  let registered = false;
  await fromDisk.start({
    protocol: 'file:',
    serviceWorker: { register: async () => ((registered = true), undefined as unknown as ServiceWorkerRegistration) },
  });
  expect(fromDisk.state).toEqual({ kind: 'single-file' });
  expect(registered).toBe(false);
});
