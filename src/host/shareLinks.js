// Links that reproduce a panel: the lecture page scrolled to it, or the embed page alone.
import { writeParams } from './params.js';
import { lecturePrefix } from '../panels/manifest.js';

function pageUrl(page) {
  return new URL(page, window.location.href);
}

export function lectureUrl(panel, values) {
  const url = pageUrl('./index.html');
  writeParams(panel.schema, values, url.searchParams, lecturePrefix(panel.id));
  url.hash = panel.id;
  return url.toString();
}

export function embedUrl(panel, values) {
  const url = pageUrl('./embed.html');
  url.searchParams.set('panel', panel.id);
  writeParams(panel.schema, values, url.searchParams);
  return url.toString();
}

/** An <iframe> snippet; attribute values are escaped, so no state can break out of the tag. */
export function embedCode(panel, values, { width = 960, height = 720 } = {}) {
  const escape = (s) => String(s).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
  return `<iframe src="${escape(embedUrl(panel, values))}" width="${width}" height="${height}" `
    + `style="border:0" loading="lazy" title="${escape(`Fresnel Lab: ${panel.title}`)}" allow="fullscreen; clipboard-write"></iframe>`;
}
