/** A render worker that dies on its first message, for testing how the pool recovers. */
import { parentPort } from 'node:worker_threads';

parentPort?.on('message', () => {
  throw new Error('the test worker crashed on purpose');
});
