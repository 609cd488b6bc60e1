// @ts-check
// The manifest of a SCORM 1.2 package (ADL, "SCORM Version 1.2 Content Aggregation Model",
// 2001, §2.3: imsmanifest.xml in IMS Content Packaging 1.1.2): one organization with one item, a
// single SCO, the homework page, with the files it needs. Moodle, Canvas, Blackboard and other
// LMSs import it as an activity whose score goes to their gradebook.

// XML 1.0 has no place for most control characters (§2.2), so they go before escaping.
// eslint-disable-next-line no-control-regex
const escapeXml = (/** @type {unknown} */ text) => String(text).replace(/[\x00-\x08\x0B\x0C\x0E-\x1F]/g, '')
  .replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/**
 * title: the sheet's; identifier: letters, digits and dashes; files: the package's paths, the SCO first.
 * @param {{ title: string, identifier: string, files: string[] }} what
 */
export function scormManifest({ title, identifier, files }) {
  const id = String(identifier).replace(/[^A-Za-z0-9-]/g, '-');
  const name = escapeXml(title);
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${id}" version="1.0"
  xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"
  xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"
  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>1.2</schemaversion>
  </metadata>
  <organizations default="${id}-org">
    <organization identifier="${id}-org">
      <title>${name}</title>
      <item identifier="${id}-item" identifierref="${id}-sco" isvisible="true">
        <title>${name}</title>
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="${id}-sco" type="webcontent" adlcp:scormtype="sco" href="${escapeXml(files[0])}">
${files.map((f) => `      <file href="${escapeXml(f)}"/>`).join('\n')}
    </resource>
  </resources>
</manifest>
`;
}
