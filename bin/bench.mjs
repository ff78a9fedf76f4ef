#!/usr/bin/env node
// `npm run bench`: registers tsx so that Node runs the TypeScript sources, then runs the benchmark.
import { register } from 'tsx/esm/api';

register();
await import('../bench/run-bench.ts');
