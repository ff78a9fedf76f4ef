import { issueText } from '../../src/i18n/issue-text.ts';
import { issueLine, wordedIssue } from '../../src/util/issue.ts';
import { afterAll, describe, expect, it, vi } from 'vitest';
import { decodeSceneLink, encodeSceneLink, sceneLinkUrl } from '../../src/app/scene-link.ts';
import { toBase64Url } from '../../src/util/base64url.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { readSceneFile, MAX_SCENE_FILE_BYTES } from '../../src/app/scene-file.ts';
import { standInPage } from '../support/page-locale.ts';

async function deflate(text: string): Promise<string> {
  const stream = new Blob([text]).stream().pipeThrough(new CompressionStream('deflate'));
  return toBase64Url(new Uint8Array(await new Response(stream).arrayBuffer()));
}

describe('scene links', () => {
  it('round-trips a scene through a short link', async () => {
    const scene = defaultScene();
    const hash = await encodeSceneLink(scene);
    expect(hash).toMatch(/^#\/s\/[A-Za-z0-9_-]+$/);
    expect(hash.length).toBeLessThan(1200);
    expect(await decodeSceneLink(hash)).toEqual({ ok: true, scene });
  });

  it('puts the fragment on the app address in place of any other', async () => {
    const url = await sceneLinkUrl(defaultScene(), 'https://school.example/quest/index.html#/teacher');
    expect(url.startsWith('https://school.example/quest/index.html#/s/')).toBe(true);
  });

  it('refuses a damaged link with a reason', async () => {
    const hash = await encodeSceneLink(defaultScene());
    const reason = async (link: string) => {
      const result = await decodeSceneLink(link);
      return result.ok ? 'opened' : result.errors.map(issueLine).join('\n');
    };
    expect(await reason(hash.slice(0, hash.length - 10))).toMatch(/cut short/);
    expect(await reason(hash.slice(0, hash.length - 8))).toBe('it was cut short or changed');
    // One character changed inside: the checksum catches it.
    const middle = Math.floor(hash.length / 2);
    const changed = hash.slice(0, middle) + (hash[middle] === 'A' ? 'B' : 'A') + hash.slice(middle + 1);
    expect(await reason(changed)).toBe('it was cut short or changed');
    expect(await reason('#/s/')).toMatch(/^it contains characters that cannot be part of a link/);
    expect(await reason('#/s/abc$def')).toMatch(/^it contains characters/);
    expect(await reason('#/a/abc')).toBe('it does not start with #/s/');
  });

  it('checks what the link holds: JSON, then the scene', async () => {
    expect(await decodeSceneLink(`#/s/${await deflate('{"version": 1,')}`)).toMatchObject({
      ok: false,
      errors: [{ path: '(root)', reason: { code: 'notJson' } }],
    });
    expect(await decodeSceneLink(`#/s/${await deflate('{"version": 1, "settings": {"supersampling": 40}}')}`)).toMatchObject({
      ok: false,
      errors: [{ path: 'settings.supersampling' }],
    });
  });

  it('stops unpacking a link that would unpack to far more than a scene', async () => {
    const bomb = `#/s/${await deflate(' '.repeat(3 * 1024 * 1024))}`;
    expect(bomb.length).toBeLessThan(10_000);
    expect(await decodeSceneLink(bomb)).toEqual({ ok: false, errors: [wordedIssue(null, 'it unpacks to more than 2048 kB, more than any scene')] });
  });
});

describe('size problems in Dutch', () => {
  afterAll(() => vi.unstubAllGlobals());

  it('are Dutch from start to end: no English detail inside the Dutch sentence', async () => {
    const speak = await standInPage();
    await speak('nl');
    const bomb = `#/s/${await deflate(' '.repeat(3 * 1024 * 1024))}`;
    expect(await decodeSceneLink(bomb)).toEqual({ ok: false, errors: [wordedIssue(null, 'uitgepakt is hij meer dan 2048 kB, groter dan welke scène ook')] });
    const tooLarge = readSceneFile('{}', MAX_SCENE_FILE_BYTES + 1);
    expect(tooLarge.ok ? [] : tooLarge.errors.map(issueText)).toEqual(['(het geheel): het bestand is 2048 kB; een scènebestand is hooguit 2048 kB']);
    await speak('en');
  });
});
