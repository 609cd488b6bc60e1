import js from '@eslint/js';
import globals from 'globals';

export default [
  { ignores: ['dist/', 'node_modules/', 'test-results/', 'playwright-report/'] },
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
    // A number a panel shows goes through src/ui/format.js: a real minus sign (U+2212) and the
    // decimals that column keeps. Markup numbers and TeX have their own helpers there and in tex.js.
    files: ['src/panels/**/*.js'],
    rules: {
      'no-restricted-syntax': ['error', {
        selector: "MemberExpression[property.name='toFixed']",
        message: 'Format numbers with src/ui/format.js: fixed, angle or sci for text, markupNumber for SVG or CSS, '
          + 'rounded for a value; texNumber (src/ui/tex.js) inside TeX.',
      }],
    },
  },
  {
    files: ['*.config.js', 'tests/**', 'bench/**', 'scripts/**', '.ci/**'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
];
