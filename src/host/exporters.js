// Exports: CSV of plotted numbers and PNG of canvases, saved as downloads; and copying text.

/** CSV text from named columns of equal length (numbers written with full float64 digits). */
export function toCsv(columns) {
  const names = Object.keys(columns);
  const rows = columns[names[0]].map((_, i) => names.map((n) => String(columns[n][i])).join(','));
  return `${names.join(',')}\n${rows.join('\n')}\n`;
}

export function downloadUrl(filename, url) {
  const link = document.createElement('a');
  link.href = url;
  link.download = filename;
  document.body.append(link);
  link.click();
  link.remove();
}

export function downloadText(filename, text, type = 'text/csv') {
  const url = URL.createObjectURL(new Blob([text], { type }));
  downloadUrl(filename, url);
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** Copies text; falls back to a prompt where the clipboard is not available (file://, old browsers). */
export async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    window.prompt('Copy this:', text);
    return false;
  }
}
