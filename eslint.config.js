import js from '@eslint/js';
import globals from 'globals';

// Every locale Intl is given comes through src/ui/safeLocale.js: browsers report some that Intl
// refuses (`en-US@posix`, `C`), and then the constructor throws. Its first argument (localeCompare's
// second) must be safeLocale(…), pageLocale() or FALLBACK_LOCALE, never left out.
const SAFE = (n) => `:not([arguments.${n}.callee.name=/^(safeLocale|pageLocale)$/], [arguments.${n}.name='FALLBACK_LOCALE'])`;
const LOCALE_RULES = [
  "NewExpression[callee.object.name='Intl']",
  "CallExpression[callee.object.name='Intl'][callee.property.name=/^[A-Z]/]",
  "CallExpression[callee.property.name=/^toLocale(Date|Time)?String$/]",
].map((selector) => `${selector}${SAFE(0)}`).concat(`CallExpression[callee.property.name='localeCompare']${SAFE(1)}`)
  .map((selector) => ({
    selector, message: 'Give Intl its locale through src/ui/safeLocale.js: safeLocale(tag), pageLocale() or FALLBACK_LOCALE.',
  }));

// One of each: outside data is read by its own keys through src/host/own.js (an inherited key such as
// `constructor` reads as absent), and an embed page's link is written by src/host/embedLink.js alone,
// so every frame, share link and deck writes the same values the same way.
const ONE_OF_EACH = [
  {
    selector: ':matches(FunctionDeclaration, VariableDeclarator[init.type=/FunctionExpression$/])[id.name=/^(own|isObject|plainObject)$/]',
    message: 'Import own and isObject from src/host/own.js.',
  },
  {
    selector: "CallExpression[callee.object.name='Reflect'][callee.property.name='get']",
    message: 'Read a field of outside data with own() of src/host/own.js: an inherited key reads as absent.',
  },
  {
    selector: "CallExpression[callee.property.name='set'][arguments.0.value='panel'], "
      + "NewExpression[callee.name='URLSearchParams'] > ObjectExpression > Property[key.name='panel']",
    message: 'Write an embed link with embedLink of src/host/embedLink.js.',
  },
];

export default [
  { ignores: ['dist/', 'node_modules/', 'test-results/', 'playwright-report/', 'docs/.vitepress/dist/', 'docs/.vitepress/cache/'] },
  js.configs.recommended,
  {
    languageOptions: {
      ecmaVersion: 2025, // import attributes: the material data is JSON that Node reads too (tests)
      sourceType: 'module',
      globals: { ...globals.browser },
    },
    rules: { 'no-unused-vars': ['error', { argsIgnorePattern: '^_' }] },
  },
  {
    // No line of the sources is longer than 140 characters (scripts/lintLines.js holds CSS, GLSL and
    // HTML to the same): a page that reads on a laptop beside the running lab, and a review diff
    // that needs no sideways scrolling.
    files: ['src/**/*.js'],
    rules: {
      'no-restricted-syntax': ['error', ...LOCALE_RULES, ...ONE_OF_EACH],
      'max-len': ['error', { code: 140, tabWidth: 2, ignoreUrls: false, ignoreStrings: false, ignoreTemplateLiterals: false }],
    },
  },
  {
    // A number a panel shows goes through src/ui/format.js: a real minus sign (U+2212) and the
    // decimals that column keeps. Markup numbers and TeX have their own helpers there and in tex.js.
    files: ['src/panels/**/*.js'],
    rules: {
      'no-restricted-syntax': ['error', ...LOCALE_RULES, ...ONE_OF_EACH, {
        selector: "MemberExpression[property.name='toFixed']",
        message: 'Format numbers with src/ui/format.js: fixed, angle or sci for text, markupNumber for SVG or CSS, '
          + 'rounded for a value; texNumber (src/ui/tex.js) inside TeX.',
      }],
    },
  },
  {
    // The one home of each (ONE_OF_EACH above).
    files: ['src/host/own.js', 'src/host/embedLink.js'],
    rules: { 'no-restricted-syntax': ['error', ...LOCALE_RULES] },
  },
  {
    files: ['*.config.js', 'tests/**', 'bench/**', 'scripts/**', '.ci/**', 'docs/.vitepress/**'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
];
