import { expect, test } from 'vitest';
import { LazyModule, RETRY_DELAYS_MS } from '../../src/util/lazy-module.ts';

/** An importer that fails its first `failures` calls, counting every call. */
function importer(failures: number) {
  const calls = { count: 0 };
  const load = async () => {
    calls.count++;
    if (calls.count <= failures) throw new TypeError(`Failed to fetch dynamically imported module (try ${calls.count})`);
    return { ok: true };
  };
  return { calls, load };
}

/** A wait that returns at once and notes how long it was asked to wait. */
function recordedWaits() {
  const waits: number[] = [];
  return { waits, wait: async (ms: number) => void waits.push(ms) };
}

test('a load that works the first time is made once and shared', async () => {
  const { calls, load } = importer(0);
  const { waits, wait } = recordedWaits();
  const module = new LazyModule(load, RETRY_DELAYS_MS, wait);
  expect(module.state).toBe('idle');
  const first = module.load();
  expect(module.state).toBe('loading');
  await expect(first).resolves.toEqual({ ok: true });
  await expect(module.load()).resolves.toEqual({ ok: true });
  expect(module.state).toBe('loaded');
  expect(calls.count).toBe(1);
  expect(waits).toEqual([]);
});

test('a load that fails for a moment is tried again after growing waits', async () => {
  const { calls, load } = importer(2);
  const { waits, wait } = recordedWaits();
  const module = new LazyModule(load, [1000, 3000], wait);
  await expect(module.load()).resolves.toEqual({ ok: true });
  expect(calls.count).toBe(3);
  expect(waits).toEqual([1000, 3000]);
  expect(module.state).toBe('loaded');
});

test('after the last try it fails for good: no more requests, the browser’s reason kept', async () => {
  const { calls, load } = importer(Infinity);
  const { waits, wait } = recordedWaits();
  const module = new LazyModule(load, [1000, 3000], wait);
  await expect(module.load()).rejects.toThrow('try 3');
  expect(module.state).toBe('failed');
  expect(module.problem).toBe('Failed to fetch dynamically imported module (try 3)');
  expect(calls.count).toBe(3);
  // Asking again (every render of the page does) answers from the failure, without loading.
  await expect(module.load()).rejects.toThrow('try 3');
  await expect(module.load()).rejects.toThrow('try 3');
  expect(calls.count).toBe(3);
  expect(waits).toEqual([1000, 3000]);
});
