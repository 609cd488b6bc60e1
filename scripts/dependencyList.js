// Every package the project installs has its line in the dependency list (the house rule: each
// dependency says why it is there). The docs build (docs/.vitepress/config.js) fails on one that has
// not, naming it. The list is a Markdown table whose first cell names packages, separated by commas,
// with notes in parentheses: "uplot (1.6.32, pinned and patched)", and a scope's packages
// shortened after the first: "@codemirror/view, state, commands".

/** The package names each row's first cell gives, as [scope or '', names]. */
function rowsOf(markdown) {
  return markdown.split('\n').filter((line) => line.startsWith('| ') && !/^\|\s*-/.test(line)).map((line) => {
    const cell = line.split('|')[1].replace(/\([^)]*\)/g, '');
    const names = cell.split(',').map((name) => name.trim()).filter(Boolean);
    return names;
  });
}

/** Whether a row lists `name`: as written, or as a scope's package shortened after the first. */
function rowLists(names, name) {
  if (names.includes(name)) return true;
  const scoped = /^(@[^/]+\/)(.+)$/.exec(name);
  return Boolean(scoped) && names.some((n) => n.startsWith(scoped[1])) && names.includes(scoped[2]);
}

/**
 * The packages of package.json (dependencies and devDependencies) that the list leaves out, in words.
 * @param {{ dependencies?: Record<string, string>, devDependencies?: Record<string, string> }} pkg
 * @param {string} markdown  the page with the list
 */
export function unlistedDependencies(pkg, markdown) {
  const rows = rowsOf(markdown);
  return Object.keys({ ...pkg.dependencies, ...pkg.devDependencies })
    .filter((name) => !rows.some((names) => rowLists(names, name)))
    .map((name) => `The package “${name}” has no line in the dependency list (docs/developer/dependencies.md): say why it is there.`);
}
