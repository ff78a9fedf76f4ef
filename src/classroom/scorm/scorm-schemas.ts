import type { ScormVersion } from './lms-api.ts';

/**
 * The schema files (XSD, and the DTDs `xml.xsd` names) of each SCORM edition, by file name.
 * SCORM's Content Aggregation Model (both editions) places them at the package's root beside
 * `imsmanifest.xml`, where the manifest's `xsi:schemaLocation` names them; a platform that
 * validates a package on import needs them there.
 * Where they come from: schemas/README.md.
 */
const FILES = {
  '1.2': import.meta.glob<string>('./schemas/1.2/*.{xsd,dtd}', { query: '?raw', import: 'default', eager: true }),
  '2004': import.meta.glob<string>('./schemas/2004/*.{xsd,dtd}', { query: '?raw', import: 'default', eager: true }),
} satisfies Record<ScormVersion, Record<string, string>>;

/** The edition's schema files: file name → text. */
export function scormSchemaFiles(version: ScormVersion): ReadonlyMap<string, string> {
  return new Map(Object.entries(FILES[version]).map(([path, text]) => [path.slice(path.lastIndexOf('/') + 1), text]));
}
