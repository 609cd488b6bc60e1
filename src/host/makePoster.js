// @ts-check
// "Export poster": for hosts that cannot embed a frame (Google Slides, a printed handout), the
// panel's picture on a slide-sized PNG with its title, its link printed in full and a QR code of
// the link, so a slide can link out to the live panel. The QR code comes from qrcode-generator,
// loaded on the first export. A copy opened from disk has a file:// link, which works on that
// computer only: its poster says so and carries no code.
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';
import { decodeImage } from './exporters.js';

const t = messages('host', english);

export const POSTER = { width: 1920, height: 1080, margin: 64 };

/**
 * The QR code of `text` as { size, isDark(row, col) } (error correction M: 15 % of the code may be lost).
 * @param {string} text
 */
export async function qrMatrix(text) {
  const { default: qrcode } = await import('qrcode-generator');
  const qr = qrcode(0, 'M');
  qr.addData(text);
  qr.make();
  return { size: qr.getModuleCount(), isDark: (/** @type {number} */ row, /** @type {number} */ col) => qr.isDark(row, col) };
}

/**
 * Where the QR code goes on the poster: its top-left corner and its module size (px).
 * @param {number} size  the code's modules on a side
 */
export function qrPlace(size) {
  const module = Math.floor(240 / (size + 8)); // a 4-module quiet zone on each side
  const side = module * (size + 8);
  return { x: POSTER.width - POSTER.margin - side, y: POSTER.height - POSTER.margin - side, module, side };
}

/**
 * text broken at any character into lines no wider than `width` in the context's font.
 * @param {{ measureText(text: string): { width: number } }} g  a 2D context
 * @param {string} text
 * @param {number} width
 */
export function wrapText(g, text, width) {
  /** @type {string[]} */
  const lines = [];
  let line = '';
  for (const char of text) {
    if (line && g.measureText(line + char).width > width) {
      lines.push(line);
      line = '';
    }
    line += char;
  }
  lines.push(line);
  return lines;
}

/**
 * picture: a PNG data URL of the panel (or null); title; link: the lecture URL of this view;
 * colours: { background, text, muted }. Resolves a PNG data URL of POSTER.width × POSTER.height, or
 * null where the browser gives no 2D canvas to draw it on.
 * @param {{ picture: string | null, title: string, link: string, colours: { background: string, text: string, muted: string } }} poster
 */
export async function makePoster({ picture, title, link, colours }) {
  const { width, height, margin } = POSTER;
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const g = canvas.getContext('2d');
  if (!g) return null; // no 2D canvas in this browser: the toolbar says so
  g.fillStyle = colours.background;
  g.fillRect(0, 0, width, height);
  g.fillStyle = colours.text;
  g.textBaseline = 'top';
  g.font = '700 64px system-ui, sans-serif';
  g.fillText(title, margin, margin, width - 2 * margin);

  const local = link.startsWith('file:');
  // A QR code holds at most 2,331 bytes at level M: a longer link (a shader lab's code) gets none.
  const matrix = local ? null : await qrMatrix(link).catch(() => null);
  const qr = qrPlace(matrix?.size ?? 25);
  // The picture fills the space between the title and the link, keeping its aspect ratio.
  const top = margin + 96;
  const bottom = qr.y - 32;
  if (picture) {
    const image = await decodeImage(picture);
    const scale = Math.min((width - 2 * margin) / image.naturalWidth, (bottom - top) / image.naturalHeight);
    const w = image.naturalWidth * scale;
    const h = image.naturalHeight * scale;
    g.imageSmoothingQuality = 'high';
    g.drawImage(image, (width - w) / 2, top + (bottom - top - h) / 2, w, h);
  }

  // The QR code, dark modules on white with its quiet zone (readable on a dark slide too).
  if (matrix) {
    g.fillStyle = '#ffffff';
    g.fillRect(qr.x, qr.y, qr.side, qr.side);
    g.fillStyle = '#000000';
    for (let row = 0; row < matrix.size; row += 1) {
      for (let col = 0; col < matrix.size; col += 1) {
        if (matrix.isDark(row, col)) g.fillRect(qr.x + (col + 4) * qr.module, qr.y + (row + 4) * qr.module, qr.module, qr.module);
      }
    }
  }

  g.fillStyle = colours.muted;
  g.font = '500 30px system-ui, sans-serif';
  const lead = t(local ? 'posterFromDisk' : matrix ? 'posterScan' : 'posterOpen');
  g.fillText(lead, margin, qr.y, qr.x - 2 * margin);
  // The link in full beside the code, wrapped at any character; a long link takes a smaller type
  // rather than being cut (the code holds all of it either way).
  g.fillStyle = colours.text;
  const room = height - margin - (qr.y + 48);
  for (const px of [28, 22, 18, 14]) {
    g.font = `${px}px ui-monospace, monospace`;
    const lines = wrapText(g, link, qr.x - 2 * margin);
    const step = Math.round(px * 1.35);
    if (lines.length * step <= room || px === 14) {
      lines.forEach((text, i) => g.fillText(text, margin, qr.y + 48 + i * step));
      break;
    }
  }
  return canvas.toDataURL('image/png');
}
