import type { LabOutcome } from '../../../quest/code-labs/code-lab-grading.ts';

/** How long one run may take, all cases together; the panel says this number. */
export const RUN_LIMIT_MS = 2000;

/** What a run came to: answers to grade, or why there are none. */
export type SandboxResult =
  | { kind: 'ran'; outcomes: LabOutcome[] }
  /** The code could not run at all (a syntax error, an exception outside the function). */
  | { kind: 'failed'; message: string; line: number | null }
  | { kind: 'no-function'; name: string }
  /** Stopped after RUN_LIMIT_MS, during case `caseIndex` (null: before the first case). */
  | { kind: 'timeout'; caseIndex: number | null }
  /** The sandbox page did not load (offline with no stored copy of the app: docs/offline.md), so the code was not run at all. */
  | { kind: 'unavailable' };

/** The sandbox page did not say it was ready: the learner's code was never run. */
export class SandboxNotLoaded extends Error {
  override readonly name = 'SandboxNotLoaded';
}

/** What a run that threw before it had an answer came to: a sandbox that never loaded, or a failure of its own. */
export function failedRun(error: unknown): Exclude<SandboxResult, { kind: 'ran' }> {
  return error instanceof SandboxNotLoaded ? { kind: 'unavailable' } : { kind: 'failed', message: String(error), line: null };
}

type SandboxMessage =
  | { type: 'ready' }
  | { type: 'case'; index: number }
  | { type: 'done'; outcomes: LabOutcome[] }
  | { type: 'failed'; message: string; line: number | null }
  | { type: 'no-function'; name: string };

/**
 * Runs the learner's function in public/code-lab-sandbox.html, framed sandboxed without
 * allow-same-origin: an opaque origin, so neither the page nor the app's stored data can be
 * reached, and a policy of its own with no network. The app frames the host page
 * public/code-lab-sandbox-host.html (same-origin, so the service worker serves it offline
 * too), which frames the sandbox and passes the messages on; the USB build frames the
 * sandbox itself (vite.usb.config.ts). The code runs in a worker of the sandbox, never on
 * the page's thread; a run that takes too long is stopped by removing the frame, which ends
 * its worker, and the next run gets a new one. docs/code-labs.md says why this is safe.
 */
export class LabSandbox {
  private frame: HTMLIFrameElement | null = null;
  private ready: Promise<HTMLIFrameElement> | null = null;

  /**
   * Runs the function on every case's arguments. `eachCase`: the sandbox says which case is
   * under way, so that a time-out can name it; a render's thousands of calls go without (a
   * message per call would cost far more than the calls).
   */
  run(code: string, name: string, cases: readonly unknown[][], { limitMs = RUN_LIMIT_MS, eachCase = true } = {}): Promise<SandboxResult> {
    return this.open().then(
      (frame) =>
        new Promise<SandboxResult>((resolve) => {
          let caseIndex: number | null = null;
          const finish = (result: SandboxResult) => {
            clearTimeout(timer);
            window.removeEventListener('message', listen);
            resolve(result);
          };
          const timer = setTimeout(() => {
            this.close();
            finish({ kind: 'timeout', caseIndex });
          }, limitMs);
          const listen = (event: MessageEvent) => {
            if (event.source !== frame.contentWindow) return;
            const message = event.data as SandboxMessage;
            if (message.type === 'case') caseIndex = message.index;
            else if (message.type === 'done') finish({ kind: 'ran', outcomes: message.outcomes });
            else if (message.type === 'failed') finish({ kind: 'failed', message: String(message.message), line: message.line });
            else if (message.type === 'no-function') finish({ kind: 'no-function', name });
          };
          window.addEventListener('message', listen);
          frame.contentWindow?.postMessage({ type: 'run', run: { code, name, cases, eachCase } }, '*');
        }),
    );
  }

  /** Removes the frame (and so any worker still running in it). */
  close(): void {
    this.frame?.remove();
    this.frame = null;
    this.ready = null;
  }

  private open(): Promise<HTMLIFrameElement> {
    this.ready ??= new Promise((resolve, reject) => {
      const frame = document.createElement('iframe');
      frame.src = 'code-lab-sandbox-host.html';
      frame.hidden = true;
      frame.tabIndex = -1;
      frame.setAttribute('aria-hidden', 'true');
      frame.title = 'code lab sandbox';
      const listen = (event: MessageEvent) => {
        if (event.source !== frame.contentWindow || (event.data as SandboxMessage)?.type !== 'ready') return;
        window.removeEventListener('message', listen);
        resolve(frame);
      };
      window.addEventListener('message', listen);
      // A frame says nothing when its page is missing: a sandbox not ready in 10 s counts as not there.
      setTimeout(() => reject(new SandboxNotLoaded('the code lab sandbox did not load')), 10_000);
      this.frame = frame;
      document.body.append(frame);
    });
    return this.ready;
  }
}
