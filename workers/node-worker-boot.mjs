// Starts a TypeScript worker thread: Node cannot load .ts in a worker by itself, and
// `--import tsx` in execArgv does not reach worker threads on Node 20, so the thread
// registers tsx first and then imports the real entry (workerData.entry, a file URL).
import { workerData } from 'node:worker_threads';
import { register } from 'tsx/esm/api';

register();
await import(workerData.entry);
