// @ts-check
// A message with an element in it (a seed in <code>, a name in <strong>): the message is written
// with a mark where the element goes and set as text around the element, so the element's content
// (outside data, such as a seed from a link) is never read as markup and the translation still
// decides where in its sentence the element stands.
const MARK = '\ue000'; // a private-use character: no message or argument of the lab holds one

/**
 * Sets `host`'s content to `write(mark)` with `element` where the mark is (once; appended at the
 * end where a translation left the mark out).
 * @param {HTMLElement} host
 * @param {(mark: string) => string} write
 * @param {Node} element
 */
export function withElement(host, write, element) {
  const text = write(MARK);
  const at = text.indexOf(MARK);
  if (at < 0) {
    host.replaceChildren(text, element);
    return host;
  }
  host.replaceChildren(...[text.slice(0, at), element, text.slice(at + MARK.length).replaceAll(MARK, '')].filter((n) => n !== ''));
  return host;
}
