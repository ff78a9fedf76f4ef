import { z } from 'zod';
import { sceneObjectSchema, sceneSchema } from './scene-schema.ts';

/**
 * The scene file's JSON Schema (draft 2020-12), for editors and other tools. It describes
 * what a file may contain, so fields with defaults are optional (`io: 'input'`). Written to
 * docs/schema/scene.schema.json by `npm run schema`; a test keeps the file up to date.
 */
export function sceneJsonSchema(): object {
  return z.toJSONSchema(sceneSchema, {
    target: 'draft-2020-12',
    io: 'input',
    override: ({ zodSchema, jsonSchema }) => {
      // Whole numbers are checked with multipleOf(1) (see wholeNumberIn); editors know "integer".
      if (jsonSchema.type === 'number' && jsonSchema.multipleOf === 1) {
        jsonSchema.type = 'integer';
        delete jsonSchema.multipleOf;
      }
      // The schema's refinements do not translate by themselves; this one can be said in
      // JSON Schema: `mesh` is required with shape "mesh" and forbidden with any other.
      if (zodSchema === sceneObjectSchema) {
        jsonSchema.if = { properties: { shape: { const: 'mesh' } }, required: ['shape'] };
        jsonSchema.then = { required: ['mesh'] };
        jsonSchema.else = { not: { required: ['mesh'] } };
      }
    },
  });
}
