// @ts-check
// A sheet as a SCORM 1.2 package (a zip an LMS imports): the single-file homework page with the
// sheet written into it, the single-file embed its panels open in, and the manifest. Built in the
// browser from the offline pages the site ships (dist/offline), so it needs no server of its own;
// the zip library is fetched only when a package is made.
import { sheetToCode } from '../sheetCodes.js';
import { scormManifest } from '../scormManifest.js';
import { hashSeed } from '../seededRandom.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);

const FILES = ['homework.html', 'embed.html', 'favicon.svg'];

/**
 * Resolves a Blob of the zip; rejects with a message a lecturer can act on.
 * @param {import('../readSheet.js').Sheet} sheet
 */
export async function buildScormPackage(sheet) {
  const base = new URL('./offline/', window.location.href);
  let texts;
  try {
    texts = await Promise.all(FILES.map(async (file) => {
      const response = await fetch(new URL(file, base));
      if (!response.ok) throw new Error(String(response.status));
      return response.text();
    }));
  } catch {
    throw new Error(t('scorm.noOfflinePages'));
  }
  const code = sheetToCode(sheet);
  // The sheet travels as a data block before the page's closing </body> (the last one: the page's
  // inlined script, which comes first, may hold the same characters).
  const page = texts[0];
  const found = page.lastIndexOf('</body>');
  const end = found < 0 ? page.length : found;
  const data = `<script type="application/json" id="fresnel-lab-sheet" data-scorm="1">${code}</script>\n`;
  const withSheet = `${page.slice(0, end)}${data}${page.slice(end)}`;
  const { zipSync, strToU8 } = await import('fflate');
  const manifest = scormManifest({ title: sheet.title, identifier: `fresnel-lab-${hashSeed(code).toString(36)}`, files: FILES });
  const zip = zipSync({
    'imsmanifest.xml': strToU8(manifest),
    [FILES[0]]: strToU8(withSheet),
    [FILES[1]]: strToU8(texts[1]),
    [FILES[2]]: strToU8(texts[2]),
  }, { level: 9 });
  return new Blob([zip], { type: 'application/zip' });
}
