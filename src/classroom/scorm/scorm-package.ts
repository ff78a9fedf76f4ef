import { strToU8, zipSync, type Zippable } from 'fflate';
import type { ScormVersion } from './lms-api.ts';
import { scormManifest } from './scorm-manifest.ts';
import { scormSchemaFiles } from './scorm-schemas.ts';

/**
 * A SCORM package: a zip with `imsmanifest.xml` and the schema files it names at its root,
 * and the app's built files beside them (IMS Content Packaging: the "package interchange
 * file"). Pictures and models are stored as they are (already compressed or small), the
 * rest deflated.
 */

export interface PackageInput {
  version: ScormVersion;
  identifier: string;
  title: string;
  /** The assignment link's fragment, with its `#`. */
  parameters: string;
  /** The app's files by their path in the build. */
  files: ReadonlyMap<string, Uint8Array>;
}

const STORED = /\.(png|jpe?g|gif|webp|woff2?)$/i;

export function scormPackage(input: PackageInput): Uint8Array {
  const manifest = scormManifest({ ...input, files: [...input.files.keys()] });
  const entries: Zippable = { 'imsmanifest.xml': strToU8(manifest) };
  for (const [name, text] of scormSchemaFiles(input.version)) entries[name] = strToU8(text);
  for (const [path, bytes] of input.files) entries[path] = [bytes, { level: STORED.test(path) ? 0 : 6 }];
  return zipSync(entries);
}

/** The file's name: the assignment's title as letters, digits and dashes, and the edition. */
export function packageFileName(title: string, version: ScormVersion): string {
  const base = title
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .replace(/[^A-Za-z0-9]+/g, '-')
    .replace(/^-|-$/g, '')
    .toLowerCase();
  return `${base || 'assignment'}-scorm-${version === '2004' ? '2004' : '1.2'}.zip`;
}
