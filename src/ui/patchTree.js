// Brings a live DOM tree to the content of a fresh one of the same shape by changing only the text
// and attributes that differ, so a formula whose numbers move keeps its nodes: the browser restyles
// and repaints a few glyphs instead of a new subtree. Trees of another shape are left alone.

/**
 * True when both trees have the same node types, tags and child counts all the way down.
 * @param {Node} a
 * @param {Node} b
 * @returns {boolean}
 */
function sameShape(a, b) {
  if (a.nodeType !== b.nodeType || a.nodeName !== b.nodeName || a.childNodes.length !== b.childNodes.length) return false;
  for (let i = 0; i < a.childNodes.length; i += 1) if (!sameShape(a.childNodes[i], b.childNodes[i])) return false;
  return true;
}

/**
 * @param {Node} live
 * @param {Node} fresh  of the same shape (sameShape)
 */
function copyInto(live, fresh) {
  if (live instanceof Text && fresh instanceof Text) {
    if (live.data !== fresh.data) live.data = fresh.data;
    return;
  }
  if (live instanceof Element && fresh instanceof Element) {
    for (const { name } of [...live.attributes]) if (!fresh.hasAttribute(name)) live.removeAttribute(name);
    for (const { name, value } of fresh.attributes) if (live.getAttribute(name) !== value) live.setAttribute(name, value);
  }
  for (let i = 0; i < live.childNodes.length; i += 1) copyInto(live.childNodes[i], fresh.childNodes[i]);
}

/**
 * Makes the children of `live` equal to the children of `fresh` in place when the two have the same
 * shape; returns whether it did (if not, nothing was changed).
 * @param {Node} live
 * @param {Node} fresh
 */
export function patchTree(live, fresh) {
  if (live.childNodes.length !== fresh.childNodes.length) return false;
  for (let i = 0; i < live.childNodes.length; i += 1) if (!sameShape(live.childNodes[i], fresh.childNodes[i])) return false;
  for (let i = 0; i < live.childNodes.length; i += 1) copyInto(live.childNodes[i], fresh.childNodes[i]);
  return true;
}
