/**
 * Runs `callback` in a later task of the event loop, after the messages that have already
 * arrived. The render worker renders one queued tile per task, so a `cancel` that arrives
 * while a tile renders is handled before the next queued tile starts.
 *
 * - Node: `setImmediate` runs in the check phase, after the poll phase has delivered pending
 *   port messages.
 * - Browsers have no `setImmediate`, and `setTimeout(fn, 0)` is clamped to 4 ms once nested
 *   five deep (HTML timers spec), which would idle a worker 4 ms per tile; a MessageChannel
 *   posting to itself has no clamp (the trick React's scheduler uses).
 */
export const nextTask: (callback: () => void) => void = typeof setImmediate === 'function' ? (callback) => void setImmediate(callback) : messageChannelTasks();

function messageChannelTasks(): (callback: () => void) => void {
  const channel = new MessageChannel();
  const callbacks: (() => void)[] = [];
  channel.port1.onmessage = () => callbacks.shift()?.();
  return (callback) => {
    callbacks.push(callback);
    channel.port2.postMessage(null);
  };
}
