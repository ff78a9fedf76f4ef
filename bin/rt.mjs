#!/usr/bin/env node
// The `rt` command: runs the prebuilt JavaScript of src/cli/rt.ts (build/node/, made when the
// project is installed), building it first if it is missing or older than its sources, so
// that no TypeScript is compiled when it starts.
import { pathToFileURL } from 'node:url';
import { ensureNodeBuild, RT_ENTRY } from '../scripts/node-build.mjs';

try {
  await ensureNodeBuild();
} catch (error) {
  process.stderr.write(`rt: could not build the command (run "npm install"): ${error instanceof Error ? error.message : error}\n`);
  process.exit(1);
}
await import(pathToFileURL(RT_ENTRY).href);
