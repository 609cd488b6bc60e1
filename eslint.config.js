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
    files: ['*.config.js', 'tests/**', 'bench/**', 'scripts/**', '.ci/**'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
];
