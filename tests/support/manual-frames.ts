import type { FrameHost } from '../../src/view/frame-scheduler.ts';

/** A frame host driven by the test: frames run only when `tick()` is called. */
export function manualFrames() {
  let queue: ((time: number) => void)[] = [];
  let time = 0;
  const host: FrameHost = {
    requestFrame: (callback) => queue.push(callback),
    cancelFrame: () => {
      queue = [];
    },
  };
  return {
    host,
    pending: () => queue.length,
    tick(ms = 16) {
      time += ms;
      const run = queue;
      queue = [];
      for (const callback of run) callback(time);
    },
  };
}
