import { z } from 'zod';

/**
 * zod compiles fast object parsers with `new Function` when it may. The built app's
 * Content-Security-Policy forbids that (no 'unsafe-eval'), and zod's probe for it would
 * log a CSP violation on every page load: so the app tells zod up front not to try.
 * Imported first by the entry point, before any schema parses.
 */
z.config({ jitless: true });
