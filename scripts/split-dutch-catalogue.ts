import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import ts from 'typescript';
import { readConfigFileAndWriteSchema } from '@lit/localize-tools/lib/config.js';
import { RuntimeLitLocalizer } from '@lit/localize-tools/lib/modes/runtime.js';
import type { LitLocalizer } from '@lit/localize-tools/lib/index.js';
import type { RuntimeOutputConfig } from '@lit/localize-tools/lib/types/modes.js';

/**
 * Splits the Dutch catalogue that `lit-localize build` writes (src/locales/nl.ts) in two: the
 * messages of the modules the first screen is built from stay in nl.ts, which is awaited
 * before that screen (src/i18n/locale.ts); the messages only later parts use (the teacher's
 * pages, the dashboard, the survey, the render window…) go to nl-later.ts, which loads while
 * the first screen is up. Together they were over the first load's budget
 * (scripts/first-load.ts).
 *
 * "The modules the first screen is built from" are those scripts/first-load.ts counts: the
 * entry, the modules it awaits by `import()` before its first render, and everything these
 * import statically. A module reached only through another `import()` is a later part. A
 * message found in both kinds of module stays in the first part.
 *
 * Run by `npm run i18n:build` after `lit-localize build`.
 */

/** Relative to the folder the script runs in: the project's root. */
const ENTRY = 'src/main.ts';
const FIRST = 'src/locales/nl.ts';
const LATER = 'src/locales/nl-later.ts';

/** The entry, the modules it loads by `import()`, and every module these import statically. */
export function firstScreenModules(program: ts.Program, entry: string): Set<string> {
  const entryFile = program.getSourceFile(resolve(entry));
  if (!entryFile) throw new Error(`${entry} is not among lit-localize's inputs`);
  const roots = [entryFile.fileName];
  entryFile.forEachChild(function find(node) {
    if (ts.isCallExpression(node) && node.expression.kind === ts.SyntaxKind.ImportKeyword && ts.isStringLiteral(node.arguments[0])) {
      roots.push(resolve(dirname(entryFile.fileName), node.arguments[0].text));
    }
    node.forEachChild(find);
  });
  const seen = new Set<string>();
  const visit = (fileName: string) => {
    if (seen.has(fileName)) return;
    const file = program.getSourceFile(fileName);
    if (!file) return;
    seen.add(fileName);
    for (const statement of file.statements) {
      const specifier = staticSpecifier(statement);
      if (specifier?.startsWith('.')) visit(resolve(dirname(fileName), specifier));
    }
  };
  roots.forEach(visit);
  return seen;
}

/** The module a statement imports or re-exports at load time, or null (types only, or no import). */
function staticSpecifier(statement: ts.Statement): string | null {
  if (ts.isImportDeclaration(statement)) {
    // `import type` is erased; `import { type A }` may leave an empty import, counted to be safe.
    if (statement.importClause?.isTypeOnly) return null;
    return (statement.moduleSpecifier as ts.StringLiteral).text;
  }
  if (ts.isExportDeclaration(statement) && statement.moduleSpecifier && !statement.isTypeOnly) {
    return (statement.moduleSpecifier as ts.StringLiteral).text;
  }
  return null;
}

/** The catalogue's entries (`'id': text,`), by id, as written in `source`. */
export function catalogueEntries(source: string): { head: string; entries: Map<string, string> } {
  const file = ts.createSourceFile(FIRST, source, ts.ScriptTarget.Latest, true);
  let literal: ts.ObjectLiteralExpression | null = null;
  file.forEachChild(function find(node) {
    if (ts.isVariableDeclaration(node) && node.name.getText() === 'templates' && node.initializer && ts.isObjectLiteralExpression(node.initializer)) {
      literal = node.initializer;
    } else node.forEachChild(find);
  });
  if (!literal) throw new Error(`${FIRST} has no "templates" object: did lit-localize change its output?`);
  const entries = new Map<string, string>();
  for (const property of (literal as ts.ObjectLiteralExpression).properties) {
    if (!ts.isPropertyAssignment(property)) throw new Error(`${FIRST}: unexpected entry ${property.getText()}`);
    entries.set((property.name as ts.StringLiteral).text, property.getText());
  }
  const head = source.slice(0, (literal as ts.ObjectLiteralExpression).getStart());
  return { head, entries };
}

function catalogueModule(head: string, entries: string[], about: string): string {
  return `// ${about}\n${head}{\n${entries.join(',\n')}\n};\n`;
}

/** lit-localize's Dutch catalogue (`source`) as the two modules the app loads: the first screen's and the later parts'. */
export function splitDutchCatalogue(localizer: LitLocalizer, source: string): { first: string; later: string } {
  const { messages, errors } = localizer.extractSourceMessages();
  if (errors.length > 0) throw new Error(`lit-localize could not read the sources (${errors.length} errors): run npm run i18n:extract`);
  const program = (localizer as unknown as { program: ts.Program }).program;
  const firstScreen = firstScreenModules(program, ENTRY);
  const firstIds = new Set(messages.filter((message) => firstScreen.has(resolve(message.file.fileName))).map((message) => message.name));
  const { head, entries } = catalogueEntries(source);
  const first: string[] = [];
  const later: string[] = [];
  for (const [id, text] of entries) (firstIds.has(id) ? first : later).push(text);
  const made = "Split from lit-localize's output by scripts/split-dutch-catalogue.ts (npm run i18n:build).";
  return {
    first: catalogueModule(head, first, `${made} The first screen's messages.`),
    later: catalogueModule(head, later, `${made} The messages of the parts that load after the first screen.`),
  };
}

function main(): void {
  const config = readConfigFileAndWriteSchema('lit-localize.json');
  const localizer = new RuntimeLitLocalizer(config as typeof config & { output: RuntimeOutputConfig });
  const { first, later } = splitDutchCatalogue(localizer, readFileSync(FIRST, 'utf8'));
  writeFileSync(FIRST, first);
  writeFileSync(LATER, later);
}

if (process.argv[1] && resolve(process.argv[1]) === resolve('scripts/split-dutch-catalogue.ts')) main();
