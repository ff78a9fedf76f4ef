/** Writes docs/schema/scene.schema.json from the zod schema: `npm run schema`. */
import { writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { sceneJsonSchema } from '../src/scene/scene-json-schema.ts';

const file = fileURLToPath(new URL('../docs/schema/scene.schema.json', import.meta.url));
writeFileSync(file, `${JSON.stringify(sceneJsonSchema(), null, 2)}\n`);
console.log(`wrote ${file}`);
