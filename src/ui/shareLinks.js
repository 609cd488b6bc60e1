// Links that reproduce a panel: the lecture page scrolled to it, or the embed page alone.
import { writeParams } from './params.js';

/** URL key prefix of a panel on the lecture page: the hero owns the short keys. */
export function lecturePrefix(id) {
  return id === 'spheres' ? '' : `${id}.`;
}

function pageUrl(page) {
  return new URL(page, window.location.href);
}

export function lectureUrl(module, values) {
  const url = pageUrl('./index.html');
  writeParams(module.schema, values, url.searchParams, lecturePrefix(module.id));
  url.hash = module.id;
  return url.toString();
}

export function embedUrl(module, values) {
  const url = pageUrl('./embed.html');
  url.searchParams.set('panel', module.id);
  writeParams(module.schema, values, url.searchParams);
  return url.toString();
}

/** An <iframe> snippet; attribute values are escaped, so no state can break out of the tag. */
export function embedCode(module, values, { width = 960, height = 720 } = {}) {
  const escape = (s) => String(s).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
  return `<iframe src="${escape(embedUrl(module, values))}" width="${width}" height="${height}" `
    + `style="border:0" loading="lazy" title="${escape(`Fresnel Lab: ${module.title}`)}" allow="fullscreen"></iframe>`;
}
