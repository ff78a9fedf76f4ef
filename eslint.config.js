// ESLint over the whole project: JavaScript's and TypeScript's recommended rules, and lit's.
// The type checker (npm run typecheck) already does what type-aware rules would, so these
// rules read one file at a time, and the lint stays quick on a 2-core machine.
import js from '@eslint/js';
import tseslint from 'typescript-eslint';
import lit from 'eslint-plugin-lit';

const nodeGlobals = { process: 'readonly', console: 'readonly', URL: 'readonly' };

export default tseslint.config(
  { ignores: ['dist/', 'dist-usb/', 'build/', 'node_modules/', 'src/locales/', 'test-results/', 'playwright-report/'] },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  lit.configs['flat/recommended'],
  {
    rules: {
      // `const { removed: _removed, ...rest } = x` drops a field; a leading _ marks a name kept for its place.
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_', varsIgnorePattern: '^_', ignoreRestSiblings: true }],
    },
  },
  // The plain-JavaScript launchers run in Node; TypeScript files get Node's names from @types/node.
  { files: ['**/*.mjs', '**/*.js'], languageOptions: { globals: nodeGlobals } },
  // Tests take saved JSON apart to damage it on purpose, field by field.
  { files: ['tests/**', 'e2e/**'], rules: { '@typescript-eslint/no-explicit-any': 'off' } },
);
