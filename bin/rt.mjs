#!/usr/bin/env node
// The `rt` command: registers tsx so that Node runs the TypeScript sources, then starts it.
import { register } from 'tsx/esm/api';

register();
await import('../src/cli/rt.ts');
