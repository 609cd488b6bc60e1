// Export PNG for the stability panel: both maps side by side on one image, each with its title
// and counts, so the file makes sense away from the page.
import { cssVar } from '../../ui/theme.js';
import { CLASS_NAMES } from '../../methods/stabilityMap.js';
import { classLabel } from './classLabels.js';
import { CLASS_COLORS } from './drawMap.js';
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

const t = messages('panelsShared', english);

/** parts: [{ canvas, title, map }]; heading: the method. Returns a PNG data URL. */
export function composePng(parts, heading) {
  const scale = parts[0]?.canvas.width / Math.max(1, parts[0]?.canvas.getBoundingClientRect().width) || 1;
  const font = 18 * scale;
  const gap = 16 * scale;
  const head = font * 2.2;
  const foot = font * 1.5 * (CLASS_NAMES.length + 0.5);
  const width = parts.reduce((w, p) => w + p.canvas.width, 0) + gap * (parts.length + 1);
  const height = Math.max(...parts.map((p) => p.canvas.height), 1) + head * 2 + foot;
  const out = document.createElement('canvas');
  out.width = Math.round(width);
  out.height = Math.round(height);
  const g = out.getContext('2d');
  g.fillStyle = cssVar('--panel', '#161b22');
  g.fillRect(0, 0, out.width, out.height);
  g.fillStyle = cssVar('--text', '#fff');
  g.textBaseline = 'middle';
  g.font = `700 ${font * 1.1}px system-ui, sans-serif`;
  g.fillText(heading, gap, head / 2);
  let x = gap;
  for (const { canvas, title, map } of parts) {
    g.fillStyle = cssVar('--text', '#fff');
    g.font = `700 ${font}px system-ui, sans-serif`;
    g.fillText(title, x, head * 1.5);
    g.drawImage(canvas, x, head * 2);
    g.font = `${font}px system-ui, sans-serif`;
    CLASS_NAMES.forEach((cls, k) => {
      const y = head * 2 + canvas.height + font * 1.5 * (k + 0.8);
      g.fillStyle = cssVar(CLASS_COLORS[k]);
      g.fillRect(x, y - font * 0.4, font * 0.8, font * 0.8);
      g.fillStyle = cssVar('--text', '#fff');
      g.fillText(t('classCount', { label: classLabel(cls), count: String(map.counts[cls]) }), x + font * 1.2, y);
    });
    x += canvas.width + gap;
  }
  return out.toDataURL('image/png');
}
