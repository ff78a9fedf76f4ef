// The app's entry point: the language first (so the first render is already in it), then the
// elements, which do the rest when they connect.
import './util/zod-jitless.ts';
import { startLocale } from './i18n/locale.ts';

await startLocale();
await import('./ui/shell/rt-app.ts');
