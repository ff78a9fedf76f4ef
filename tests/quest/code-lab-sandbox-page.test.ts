import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

/**
 * The sandbox page (public/code-lab-sandbox.html) runs only its own inline script, named by
 * its hash in its policy: an edit of the script that does not update the hash would leave the
 * code labs unable to run. The app's own policy keeps eval out (vite.config.ts).
 */
const page = readFileSync(new URL('../../public/code-lab-sandbox.html', import.meta.url), 'utf8');
const policy = /http-equiv="Content-Security-Policy" content="([^"]+)"/.exec(page)?.[1] ?? '';

describe('the code lab sandbox page', () => {
  it('names its one script by hash, and allows no network or other script', () => {
    const scripts = [...page.matchAll(/<script>([\s\S]*?)<\/script>/g)].map((match) => match[1]);
    expect(scripts).toHaveLength(1);
    const hash = createHash('sha256').update(scripts[0]!).digest('base64');
    expect(policy.split('; ')).toEqual(["default-src 'none'", `script-src 'sha256-${hash}' 'unsafe-eval'`, 'worker-src blob:']);
  });

  it('is where eval is allowed, not the app', () => {
    const config = readFileSync(new URL('../../vite.config.ts', import.meta.url), 'utf8');
    expect(config).toContain(`"script-src 'self'",`);
    expect(config).not.toContain('unsafe-eval');
  });
});
