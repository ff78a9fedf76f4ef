import type { ScormVersion } from './lms-api.ts';

/**
 * A SCORM package's `imsmanifest.xml` (IMS Content Packaging, as SCORM profiles it): one
 * organization with one item, the assignment, launching one SCO, the game. The SCO's
 * resource is `index.html`; the assignment rides in the item's `parameters` (its link's
 * fragment, `#/a/1.…`), which the platform appends to the resource's address at launch
 * (SCORM 2004 4th ed. CAM §3.4.1.12 and §4.4.5; SCORM 1.2 CAM §2.3.5.3), so the game opens
 * the assignment as it does from a link. Every file of the package is listed in the resource.
 *
 * The two editions differ in namespaces, in the `schemaversion` ("1.2" or "2004 4th Edition")
 * and in the spelling of `adlcp:scormtype` (1.2) / `adlcp:scormType` (2004). The XSD files
 * the `schemaLocation` names travel in the package (scorm-schemas.ts), and the manifest is
 * validated against them in tests/classroom/scorm/scorm-manifest-xsd.test.ts.
 */

export interface ManifestInput {
  version: ScormVersion;
  /** Unique per assignment: a platform that imports the package again updates it instead of adding a second. */
  identifier: string;
  title: string;
  /** The assignment link's fragment, with its `#`. */
  parameters: string;
  /** The package's files, as paths inside it. */
  files: readonly string[];
}

export const LAUNCH_FILE = 'index.html';

const NAMESPACES: Record<ScormVersion, string> = {
  '1.2': [
    'xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"',
    'xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"',
    'xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"',
    'xsi:schemaLocation="http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd"',
  ].join('\n  '),
  '2004': [
    'xmlns="http://www.imsglobal.org/xsd/imscp_v1p1"',
    'xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_v1p3"',
    'xmlns:adlseq="http://www.adlnet.org/xsd/adlseq_v1p3"',
    'xmlns:adlnav="http://www.adlnet.org/xsd/adlnav_v1p3"',
    'xmlns:imsss="http://www.imsglobal.org/xsd/imsss"',
    'xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"',
    'xsi:schemaLocation="http://www.imsglobal.org/xsd/imscp_v1p1 imscp_v1p1.xsd http://www.adlnet.org/xsd/adlcp_v1p3 adlcp_v1p3.xsd http://www.adlnet.org/xsd/adlseq_v1p3 adlseq_v1p3.xsd http://www.adlnet.org/xsd/adlnav_v1p3 adlnav_v1p3.xsd http://www.imsglobal.org/xsd/imsss imsss_v1p0.xsd"',
  ].join('\n  '),
};

export const SCHEMA_VERSION: Record<ScormVersion, string> = { '1.2': '1.2', '2004': '2004 4th Edition' };

export function scormManifest(input: ManifestInput): string {
  const { version } = input;
  const scormType = version === '2004' ? 'adlcp:scormType' : 'adlcp:scormtype';
  const title = escapeXml(input.title);
  const files = [LAUNCH_FILE, ...input.files.filter((file) => file !== LAUNCH_FILE)];
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${escapeXml(input.identifier)}" version="1"
  ${NAMESPACES[version]}>
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>${SCHEMA_VERSION[version]}</schemaversion>
  </metadata>
  <organizations default="assignment">
    <organization identifier="assignment">
      <title>${title}</title>
      <item identifier="game" identifierref="game-sco" parameters="${escapeXml(input.parameters)}">
        <title>${title}</title>
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="game-sco" type="webcontent" ${scormType}="sco" href="${LAUNCH_FILE}">
${files.map((file) => `      <file href="${escapeXml(file)}"/>`).join('\n')}
    </resource>
  </resources>
</manifest>
`;
}

function escapeXml(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;').replace(/'/g, '&apos;');
}
