import { describe, expect, it } from 'vitest';
import { toBase64Url } from '../../src/util/base64url.ts';
import { packJson, unpackJson } from '../../src/util/packed-json.ts';
import { deflate } from '../../src/util/zlib-bytes.ts';

describe("packed JSON (the scene and assignment links' payload)", () => {
  it('unpacks what it packed', async () => {
    const value = { name: 'ë €', list: [1, 2.5, null], nested: { ok: true } };
    const packed = await packJson(value);
    expect(packed).toMatch(/^[A-Za-z0-9_-]+$/);
    expect(await unpackJson(packed, 1024)).toEqual({ ok: true, value });
  });

  it('says which check failed: characters, checksum, size, JSON', async () => {
    const packed = await packJson({ a: 'x'.repeat(200) });
    expect(await unpackJson('not a link!', 1024)).toEqual({ ok: false, problem: 'not-base64url' });
    expect(await unpackJson('', 1024)).toEqual({ ok: false, problem: 'not-base64url' });
    expect(await unpackJson(packed.slice(0, -3), 1024)).toEqual({ ok: false, problem: 'damaged' });
    expect(await unpackJson(packed, 100)).toEqual({ ok: false, problem: 'too-large', limit: 100 });
    const notJson = toBase64Url(await deflate(new TextEncoder().encode('{"a": ')));
    expect(await unpackJson(notJson, 1024)).toMatchObject({ ok: false, problem: 'not-json', issue: { path: '(root)', reason: { code: 'notJson' } } });
  });
});
