// The lab's style sheets lay out by reading direction (margin-inline-start, text-align: start, …), so a
// right-to-left language needs no CSS of its own. This finds what does not: a physical left or right
// (margin-left, left:, text-align: right, float: left, a four-value margin or padding whose sides
// differ, border radii that differ left and right), left unmarked. Where a left or right is geometry
// (a label over the left half of a picture) its declaration says so with a comment holding
// `physical:` on its own line or the line before. It also finds words written in CSS (content: 'x'),
// which no catalogue can translate, and a `direction` with no comment to say why.
// Logical properties: https://www.w3.org/TR/css-logical-1/

const SIDES = /^(margin|padding|border|inset|scroll-margin|scroll-padding)-(left|right)(-(width|style|color))?$/;
const CORNER = /^border-(top|bottom)-(left|right)-radius$/;
const KEYWORD = { 'text-align': /^(left|right)\b/, 'text-align-last': /^(left|right)\b/, float: /^(left|right)\b/, clear: /^(left|right)\b/ };
const FOUR_SIDED = new Set(['margin', 'padding', 'inset', 'border-width', 'border-style', 'border-color', 'scroll-margin', 'scroll-padding']);

/** A value's space-separated parts, with calc(…) and other functions kept whole. */
function parts(value) {
  const out = [];
  let depth = 0;
  let word = '';
  for (const ch of value.trim()) {
    if (ch === '(') depth += 1;
    if (ch === ')') depth -= 1;
    if (/\s/.test(ch) && !depth) {
      if (word) out.push(word);
      word = '';
    } else word += ch;
  }
  if (word) out.push(word);
  return out;
}

/** Why `property: value` is a physical left or right, or null. */
export function physicalReason(property, value) {
  const name = property.toLowerCase();
  const v = value.replace(/!important/i, '').trim().toLowerCase();
  if (SIDES.test(name) || CORNER.test(name)) return `${name} (use its inline-start/end form)`;
  if (name === 'left' || name === 'right') return `${name}: (use inset-inline-start/end)`;
  if (KEYWORD[name]?.test(v)) return `${name}: ${v} (use start or end)`;
  const p = parts(v);
  if (FOUR_SIDED.has(name) && p.length === 4 && p[1] !== p[3]) return `${name} with different left and right (use ${name}-inline and -block)`;
  if (name === 'border-radius' && !v.includes('/')) {
    const [tl, tr = tl, br = tl, bl = tr] = p;
    if (tl !== tr || br !== bl) return 'border-radius different left and right (use border-start-start-radius …)';
  }
  return null;
}

/**
 * Every declaration of a style sheet with its line and the comments near it: walks the text once,
 * skipping strings, so that a `;` or a brace in content: '…' ends nothing.
 * @returns {{ property: string, value: string, line: number, marked: boolean, explained: boolean }[]}
 */
export function declarations(css) {
  const comments = []; // { first, last, text }
  const found = [];
  let line = 1;
  let buffer = '';
  let start = 1; // the line of the buffer's first visible character
  const flush = (isDeclaration) => {
    const text = buffer.trim();
    buffer = '';
    if (!isDeclaration || !text) return;
    const colon = text.indexOf(':');
    if (colon < 0) return;
    found.push({ property: text.slice(0, colon).trim(), value: text.slice(colon + 1).trim(), line: start, end: line });
  };
  let depth = 0;
  for (let i = 0; i < css.length; i += 1) {
    const ch = css[i];
    if (ch === '/' && css[i + 1] === '*') {
      const close = css.indexOf('*/', i + 2);
      const stop = close < 0 ? css.length : close + 2;
      const text = css.slice(i, stop);
      const lines = text.split('\n').length - 1;
      comments.push({ first: line, last: line + lines, text });
      line += lines;
      i = stop - 1;
      continue;
    }
    if (ch === '"' || ch === "'") {
      let j = i + 1;
      while (j < css.length && css[j] !== ch) j += css[j] === '\\' ? 2 : 1;
      if (!buffer.trim()) start = line;
      buffer += css.slice(i, j + 1);
      i = j;
      continue;
    }
    if (ch === '\n') line += 1;
    if (ch === '{') {
      depth += 1;
      buffer = '';
    } else if (ch === '}') {
      flush(depth > 0);
      depth -= 1;
    } else if (ch === ';') flush(depth > 0);
    else {
      if (!buffer.trim() && !/\s/.test(ch)) start = line;
      buffer += ch;
    }
  }
  return found.map(({ property, value, line: first, end }) => {
    const near = (before) => comments.filter((c) => c.last >= first - before && c.first <= end);
    return {
      property, value, line: first,
      marked: near(1).some((c) => /physical:/.test(c.text)),
      explained: near(3).length > 0,
    };
  });
}

/** What a style sheet does against reading direction: one line each, 'line N: why'. */
export function directionProblems(css) {
  return declarations(css).flatMap(({ property, value, line, marked, explained }) => {
    const problems = [];
    const reason = physicalReason(property, value);
    if (reason && !marked) problems.push(`line ${line}: ${reason}`);
    if (property === 'content' && /\p{L}{2,}/u.test(value.replace(/attr\([^)]*\)|counter\([^)]*\)|var\([^)]*\)/g, ''))) {
      problems.push(`line ${line}: words in content: ${value} (a catalogue message cannot reach CSS)`);
    }
    if (property === 'direction' && !explained) problems.push(`line ${line}: direction: ${value} without a comment saying why`);
    return problems;
  });
}
