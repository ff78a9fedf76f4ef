import { checkFirstLoad, firstLoad } from './first-load.ts';

// `npm run check:size [dist]`: fails (exit code 1) when a student's first load of JavaScript
// is over its budget. Run after `vite build`.
const dist = process.argv[2] ?? 'dist';
try {
  const { ok, lines } = checkFirstLoad(firstLoad(dist));
  console.log(lines.join('\n'));
  process.exitCode = ok ? 0 : 1;
} catch (error) {
  console.error(`Cannot measure ${dist}/: ${error instanceof Error ? error.message : String(error)} (run vite build first)`);
  process.exitCode = 1;
}
