/**
 * The waits before the second and third try of a module loaded on demand. A load fails when
 * the connection drops for a moment (worth a retry), when the page is offline with no
 * stored copy, or when a newer build has replaced this page's files on the server (no retry
 * helps: only a reload does). Three tries in about four seconds cover the first case; after
 * that the page says what happened and offers a reload, instead of asking again and again
 * (an unbounded retry sent thousands of requests a second).
 */
export const RETRY_DELAYS_MS: readonly number[] = [1000, 3000];

const sleep = (ms: number) => new Promise<void>((resolve) => setTimeout(resolve, ms));

export type LazyModuleState = 'idle' | 'loading' | 'loaded' | 'failed';

/**
 * A part of the app whose code is loaded when it is first needed (a dynamic `import()`):
 * loaded once, tried again a bounded number of times with growing waits, and, once those
 * tries have failed, failed for good (until the page is reloaded): asking again gives the
 * same failure without a request.
 */
export class LazyModule<T> {
  private promise: Promise<T> | null = null;
  private current: LazyModuleState = 'idle';
  private reason = '';

  constructor(
    private readonly importer: () => Promise<T>,
    private readonly delays: readonly number[] = RETRY_DELAYS_MS,
    private readonly wait: (ms: number) => Promise<void> = sleep,
  ) {}

  get state(): LazyModuleState {
    return this.current;
  }

  /** Why the last try failed (the browser's words), once the state is 'failed'; '' before. */
  get problem(): string {
    return this.reason;
  }

  /** The module: the first call starts loading, later ones share that load and its outcome. */
  load(): Promise<T> {
    this.promise ??= this.tryAll();
    return this.promise;
  }

  private async tryAll(): Promise<T> {
    this.current = 'loading';
    for (let attempt = 0; ; attempt++) {
      try {
        const module = await this.importer();
        this.current = 'loaded';
        return module;
      } catch (error) {
        if (attempt >= this.delays.length) {
          this.current = 'failed';
          this.reason = error instanceof Error ? error.message : String(error);
          throw error;
        }
        await this.wait(this.delays[attempt]!);
      }
    }
  }
}
