// @ts-check
// Exports: CSV of plotted numbers and PNG of canvases, saved as downloads; and copying text.

/**
 * CSV text from named columns of equal length (numbers written with full float64 digits).
 * @param {Record<string, ArrayLike<number | string>>} columns
 */
export function toCsv(columns) {
  const names = Object.keys(columns);
  const rows = Array.from(columns[names[0]], (_, i) => names.map((n) => String(columns[n][i])).join(','));
  return `${names.join(',')}\n${rows.join('\n')}\n`;
}

/** @param {string} filename @param {string} url */
export function downloadUrl(filename, url) {
  const link = document.createElement('a');
  link.href = url;
  link.download = filename;
  document.body.append(link);
  link.click();
  link.remove();
}

/** @param {string} filename @param {Blob} blob */
export function downloadBlob(filename, blob) {
  const url = URL.createObjectURL(blob);
  downloadUrl(filename, url);
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** @param {string} filename @param {string} text */
export function downloadText(filename, text, type = 'text/csv') {
  downloadBlob(filename, new Blob([text], { type }));
}

/**
 * An image decoded from a URL (rejects where it cannot be decoded).
 * @param {string} url
 */
export async function decodeImage(url) {
  const image = new Image();
  image.src = url;
  await image.decode();
  return image;
}

/**
 * A PNG data URL redrawn to fit inside width × height (either may be null: that side follows the
 * aspect ratio; both null: the picture's own size). Resolves { url, width, height }; where the image
 * cannot be decoded (a CSP refusing data: images) the picture as it is, its size unknown (null).
 * @param {string} url
 * @param {number | null} [width]
 * @param {number | null} [height]
 * @returns {Promise<{ url: string, width: number | null, height: number | null }>}
 */
export async function resizePng(url, width = null, height = null) {
  let image;
  try {
    image = await decodeImage(url);
  } catch {
    return { url, width: null, height: null };
  }
  const scale = Math.min(width ? width / image.naturalWidth : Infinity, height ? height / image.naturalHeight : Infinity);
  const fit = Number.isFinite(scale) ? scale : 1;
  const canvas = document.createElement('canvas');
  canvas.width = Math.max(1, Math.round(image.naturalWidth * fit));
  canvas.height = Math.max(1, Math.round(image.naturalHeight * fit));
  const context = canvas.getContext('2d');
  if (!context) return { url, width: null, height: null }; // no 2D canvas here: the picture as it is
  context.imageSmoothingQuality = 'high';
  context.drawImage(image, 0, 0, canvas.width, canvas.height);
  return { url: canvas.toDataURL('image/png'), width: canvas.width, height: canvas.height };
}

/**
 * Copies text to the clipboard; false where it is refused (file://, a frame without clipboard-write).
 * @param {string} text
 */
export async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    return false;
  }
}

/**
 * Where the clipboard is refused: the text in a read-only field after `anchor`, selected and
 * focused, so Ctrl+C (or a long press) copies it. It goes away when it loses focus or on Escape.
 * @param {HTMLElement} anchor
 * @param {string} text
 * @param {string} label  the field's accessible name
 */
export function offerForCopy(anchor, text, label) {
  anchor.parentElement?.querySelector('.copy-fallback')?.remove();
  const field = document.createElement('textarea');
  field.className = 'copy-fallback';
  field.readOnly = true;
  field.rows = 3;
  field.value = text;
  field.setAttribute('aria-label', label);
  const close = () => {
    field.removeEventListener('blur', close); // removing a focused field blurs it
    field.remove();
  };
  field.addEventListener('blur', close);
  field.addEventListener('keydown', (event) => { if (event.key === 'Escape') { close(); anchor.focus(); } });
  anchor.after(field);
  field.focus();
  field.select();
  return field;
}
