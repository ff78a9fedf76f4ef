import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { sceneJsonSchema } from '../../src/scene/scene-json-schema.ts';

describe('docs/schema/scene.schema.json', () => {
  it('is what the zod schema generates now (if not: run `npm run schema`)', () => {
    const onDisk: unknown = JSON.parse(readFileSync(new URL('../../docs/schema/scene.schema.json', import.meta.url), 'utf8'));
    expect(onDisk, 'docs/schema/scene.schema.json is out of date: run `npm run schema`').toEqual(sceneJsonSchema());
  });

  it('is draft 2020-12 with a title, and needs only the version', () => {
    expect(sceneJsonSchema()).toMatchObject({
      $schema: 'https://json-schema.org/draft/2020-12/schema',
      title: 'Ray Tracer Quest scene',
      required: ['version'],
      additionalProperties: false,
    });
  });
});
