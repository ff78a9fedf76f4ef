import { DOMParser } from '@xmldom/xmldom';
import { unzipSync, strFromU8 } from 'fflate';
import { describe, expect, it } from 'vitest';
import type { ScormVersion } from '../../../src/classroom/scorm/lms-api.ts';
import { scormManifest, SCHEMA_VERSION } from '../../../src/classroom/scorm/scorm-manifest.ts';
import { packageFileName, scormPackage } from '../../../src/classroom/scorm/scorm-package.ts';
import { scormSchemaFiles } from '../../../src/classroom/scorm/scorm-schemas.ts';

// The manifest checked as a platform reads it: XML, the namespaces of each edition, the
// schema version, and every reference resolving (organization → item → resource → files in
// the zip). The XSDs' own rules are checked by libxml2 in scorm-manifest-xsd.test.ts. xmldom (a dependency of Workbox's)
// lets some malformed XML pass, so the escaping is checked on the text as well, and the
// browser test (e2e/scorm.spec.ts) parses the built package's manifest with Chromium's
// strict XML parser.

const NS: Record<ScormVersion, { cp: string; adlcp: string; scormType: string }> = {
  '1.2': { cp: 'http://www.imsproject.org/xsd/imscp_rootv1p1p2', adlcp: 'http://www.adlnet.org/xsd/adlcp_rootv1p2', scormType: 'scormtype' },
  '2004': { cp: 'http://www.imsglobal.org/xsd/imscp_v1p1', adlcp: 'http://www.adlnet.org/xsd/adlcp_v1p3', scormType: 'scormType' },
};

const FILES = new Map<string, Uint8Array>([
  ['index.html', new TextEncoder().encode('<!doctype html><title>game</title>')],
  ['assets/index-abc.js', new TextEncoder().encode('console.log(1)')],
  ['icons/icon-192.png', new Uint8Array([137, 80, 78, 71])],
]);
const PARAMETERS = '#/a/1.eJyrVipLzSlVslIqS8wpTVWqBQA1hwXd';
const TITLE = 'Lichtstralen & <schaduw> "5H2"';

function parse(text: string): Document {
  const errors: string[] = [];
  const document = new DOMParser({ errorHandler: (level: string, message: string) => void errors.push(`${level}: ${message}`) }).parseFromString(
    text,
    'text/xml',
  );
  expect(errors).toEqual([]);
  // Every & starts an entity; no < or > inside an attribute value.
  expect(text.match(/&(?!(amp|lt|gt|quot|apos);)/g)).toBeNull();
  expect(text.match(/="[^"]*[<>][^"]*"/g)).toBeNull();
  return document as unknown as Document;
}

const children = (parent: Element, ns: string, name: string): Element[] =>
  Array.from(parent.childNodes).filter(
    (node): node is Element => node.nodeType === 1 && (node as Element).namespaceURI === ns && (node as Element).localName === name,
  );

function only(parent: Element, ns: string, name: string): Element {
  const found = children(parent, ns, name);
  expect(found, `one <${name}> in <${parent.localName}>`).toHaveLength(1);
  return found[0];
}

describe.each(['1.2', '2004'] as const)('the SCORM %s package', (version) => {
  const zip = unzipSync(scormPackage({ version, identifier: 'rtq-0a1b2c3d', title: TITLE, parameters: PARAMETERS, files: FILES }));
  const { cp, adlcp, scormType } = NS[version];

  it('holds imsmanifest.xml and the schemas it names at its root, and every file of the build, unchanged', () => {
    const schemas = [...scormSchemaFiles(version).keys()];
    expect(Object.keys(zip).sort()).toEqual(['imsmanifest.xml', ...schemas, ...FILES.keys()].sort());
    for (const [path, bytes] of FILES) expect(zip[path]).toEqual(bytes);
    const manifest = parse(strFromU8(zip['imsmanifest.xml'])).documentElement;
    const locations = manifest.getAttributeNS('http://www.w3.org/2001/XMLSchema-instance', 'schemaLocation')!.split(/\s+/);
    const named = locations.filter((_, index) => index % 2 === 1);
    for (const file of named) expect(schemas, `${file} is in the package`).toContain(file);
  });

  it('has a well-formed manifest in the edition’s namespace, with its schema version', () => {
    const manifest = parse(strFromU8(zip['imsmanifest.xml'])).documentElement;
    expect([manifest.namespaceURI, manifest.localName]).toEqual([cp, 'manifest']);
    expect(manifest.getAttribute('identifier')).toBe('rtq-0a1b2c3d');
    const metadata = only(manifest, cp, 'metadata');
    expect(only(metadata, cp, 'schema').textContent).toBe('ADL SCORM');
    expect(only(metadata, cp, 'schemaversion').textContent).toBe(version === '2004' ? '2004 4th Edition' : '1.2');
    expect(SCHEMA_VERSION[version]).toBe(only(metadata, cp, 'schemaversion').textContent);
    // xsi:schemaLocation pairs each namespace used with its XSD.
    const locations = manifest.getAttributeNS('http://www.w3.org/2001/XMLSchema-instance', 'schemaLocation')!.split(/\s+/);
    expect(locations.length % 2).toBe(0);
    expect(locations).toEqual(expect.arrayContaining([cp, adlcp]));
  });

  it('launches one SCO, the game, with the assignment in the item’s parameters; every reference resolves', () => {
    const manifest = parse(strFromU8(zip['imsmanifest.xml'])).documentElement;
    const organizations = only(manifest, cp, 'organizations');
    const organization = only(organizations, cp, 'organization');
    expect(organizations.getAttribute('default')).toBe(organization.getAttribute('identifier'));
    expect(only(organization, cp, 'title').textContent).toBe(TITLE);
    const item = only(organization, cp, 'item');
    expect(only(item, cp, 'title').textContent).toBe(TITLE);
    expect(item.getAttribute('parameters')).toBe(PARAMETERS);
    const resources = children(only(manifest, cp, 'resources'), cp, 'resource');
    expect(resources).toHaveLength(1);
    const [resource] = resources;
    expect(item.getAttribute('identifierref')).toBe(resource.getAttribute('identifier'));
    expect(resource.getAttributeNS(adlcp, scormType)).toBe('sco');
    expect(resource.getAttribute('type')).toBe('webcontent');
    const files = children(resource, cp, 'file').map((file) => file.getAttribute('href')!);
    expect(files).toContain(resource.getAttribute('href'));
    expect(files.sort()).toEqual([...FILES.keys()].sort());
    for (const file of files) expect(zip[file], file).toBeDefined();
    // Identifiers are xs:ID: unique, and names (no leading digit, no spaces).
    const ids = [manifest, organization, item, resource].map((element) => element.getAttribute('identifier')!);
    expect(new Set(ids).size).toBe(ids.length);
    for (const id of ids) expect(id).toMatch(/^[A-Za-z_][\w.-]*$/);
  });
});

describe('the manifest and the file name', () => {
  it('escape what XML and file systems cannot take', () => {
    const text = scormManifest({ version: '2004', identifier: 'x', title: 'a & b <c>', parameters: '#/a/1.x', files: [] });
    expect(text).toContain('<title>a &amp; b &lt;c&gt;</title>');
    expect(packageFileName('Licht & schaduw: 5H2', '2004')).toBe('licht-schaduw-5h2-scorm-2004.zip');
    expect(packageFileName('Été', '1.2')).toBe('ete-scorm-1.2.zip');
    expect(packageFileName('???', '1.2')).toBe('assignment-scorm-1.2.zip');
  });
});
