import { readFileSync } from 'node:fs';
import { afterFirstScreenLines, afterFirstScreen, checkFirstLoad, firstLoad, readManifest } from './first-load.ts';

// `npm run check:size [dist]`: fails (exit code 1) when a student's first load of JavaScript,
// in English or in any language the app is translated into (lit-localize.json), is over its budget. Run after `vite build`.
const dist = process.argv[2] ?? 'dist';
try {
  const manifest = readManifest(dist);
  const { sourceLocale, targetLocales } = JSON.parse(readFileSync('lit-localize.json', 'utf8')) as { sourceLocale: string; targetLocales: string[] };
  const locales = [sourceLocale, ...targetLocales];
  const checks = locales.map((locale) => checkFirstLoad(firstLoad(dist, locale, manifest)));
  console.log([...checks.flatMap((check) => check.lines), ...afterFirstScreenLines(afterFirstScreen(dist, manifest))].join('\n'));
  process.exitCode = checks.every((check) => check.ok) ? 0 : 1;
} catch (error) {
  console.error(`Cannot measure ${dist}/: ${error instanceof Error ? error.message : String(error)} (run vite build first)`);
  process.exitCode = 1;
}
