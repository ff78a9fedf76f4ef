import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

/**
 * The sandbox page (public/code-lab-sandbox.html) and its host page
 * (public/code-lab-sandbox-host.html) run only their own inline scripts, named by hash in their
 * policies; the host's policy holds in the sandbox too (a `srcdoc` frame inherits it), so it
 * names the sandbox's script as well. An edit of a script that does not update the hashes
 * would leave the code labs unable to run. The app's own policy keeps eval out (vite.config.ts).
 */
const read = (file: string) => readFileSync(new URL(`../../public/${file}`, import.meta.url), 'utf8');
const policyOf = (page: string) => (/http-equiv="Content-Security-Policy" content="([^"]+)"/.exec(page)?.[1] ?? '').split('; ');
const scriptsOf = (page: string) => [...page.matchAll(/<script>([\s\S]*?)<\/script>/g)].map((match) => match[1]!);
const hashOf = (script: string) => `'sha256-${createHash('sha256').update(script).digest('base64')}'`;

const sandbox = read('code-lab-sandbox.html');
const host = read('code-lab-sandbox-host.html');

describe('the code lab sandbox page', () => {
  it('names its one script by hash, and allows no network or other script', () => {
    const scripts = scriptsOf(sandbox);
    expect(scripts).toHaveLength(1);
    expect(policyOf(sandbox)).toEqual(["default-src 'none'", `script-src ${hashOf(scripts[0]!)} 'unsafe-eval'`, 'worker-src blob:']);
  });

  it('is where eval is allowed, not the app', () => {
    const config = readFileSync(new URL('../../vite.config.ts', import.meta.url), 'utf8');
    expect(config).toContain(`"script-src 'self'",`);
    expect(config).not.toContain('unsafe-eval');
  });
});

describe('the sandbox host page', () => {
  it('allows its own script and the sandbox’s, and fetches from its own origin only', () => {
    const scripts = scriptsOf(host);
    expect(scripts).toHaveLength(1);
    expect(policyOf(host)).toEqual([
      "default-src 'none'",
      `script-src ${hashOf(scripts[0]!)} ${hashOf(scriptsOf(sandbox)[0]!)} 'unsafe-eval'`,
      'worker-src blob:',
      "connect-src 'self'",
    ]);
  });
});
