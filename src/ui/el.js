// The one DOM helper every panel uses: an element with a class and text, never innerHTML.

/**
 * @template {keyof HTMLElementTagNameMap} K
 * @param {K} tag
 * @param {string | null} [className]
 * @param {string} [text]
 * @returns {HTMLElementTagNameMap[K]}
 */
export function el(tag, className, text) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

/**
 * A plain button (type="button", so it never submits a form) with its visible text.
 * @param {string} text
 * @param {string | null} [className]
 */
export function button(text, className) {
  const b = el('button', className, text);
  b.type = 'button';
  return b;
}
