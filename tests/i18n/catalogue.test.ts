// The Dutch catalogue against the source: every msg() has a Dutch translation, the XLIFF file
// is what `npm run i18n:extract` would write, and the committed generated module is what
// `npm run i18n:build` would write. It runs the real extractor of @lit/localize-tools (the
// same TypeScript analysis the CLI does), in a temporary folder, so nothing in the project
// is touched.
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { readConfigFileAndWriteSchema } from '@lit/localize-tools/lib/config.js';
import type { Message } from '@lit/localize-tools/lib/messages.js';
import type { Locale } from '@lit/localize-tools/lib/types/locale.js';
import { RuntimeLitLocalizer } from '@lit/localize-tools/lib/modes/runtime.js';
import type { RuntimeOutputConfig } from '@lit/localize-tools/lib/types/modes.js';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { splitDutchCatalogue } from '../../scripts/split-dutch-catalogue.ts';

const root = resolve(import.meta.dirname, '../..');
const TARGET = 'nl' as Locale;

/** A message as a translator reads it: its text with ${…} for each placeholder. */
function text(message: Message): string {
  return message.contents.map((part) => (typeof part === 'string' ? part : part.untranslatable)).join('');
}

describe('the Dutch catalogue', () => {
  let folder: string;
  let localizer: RuntimeLitLocalizer;

  beforeAll(() => {
    const config = readConfigFileAndWriteSchema(join(root, 'lit-localize.json'));
    if (config.output.mode !== 'runtime' || config.interchange.format !== 'xliff') throw new Error('lit-localize.json: expected runtime mode with XLIFF');
    folder = mkdtempSync(join(tmpdir(), 'rt-i18n-'));
    mkdirSync(join(folder, 'xliff'));
    copyFileSync(join(root, config.interchange.xliffDir, `${TARGET}.xlf`), join(folder, 'xliff', `${TARGET}.xlf`));
    const output: RuntimeOutputConfig = { ...config.output, outputDir: join(folder, 'locales'), localeCodesModule: join(folder, 'locales', 'locale-codes.ts') };
    localizer = new RuntimeLitLocalizer({ ...config, output, interchange: { ...config.interchange, xliffDir: join(folder, 'xliff') } });
    // The analysis type-checks all of src/: far slower than a unit test, so it runs once, here.
    localizer.extractSourceMessages();
  }, 180_000);

  afterAll(() => {
    if (folder) rmSync(folder, { recursive: true, force: true });
  });

  it('reads every msg() call of the source (a template with ${…} needs the str tag)', () => {
    const { messages, errors } = localizer.extractSourceMessages();
    expect(errors.map((error) => `${error.file?.fileName}: ${String(error.messageText)}`)).toEqual([]);
    expect(messages.length).toBeGreaterThan(500);
  });

  it('has a Dutch translation for every message (add it to xliff/nl.xlf, then run npm run i18n:build)', () => {
    const translated = new Set(
      (localizer.readTranslationsSync().translations.get(TARGET) ?? []).filter((message) => text(message).trim() !== '').map((message) => message.name),
    );
    const missing = localizer
      .extractSourceMessages()
      .messages.filter((message) => !translated.has(message.name))
      .map((message) => `${message.file.fileName.slice(root.length + 1)}: ${text(message)}`);
    expect(missing).toEqual([]);
  });

  it('keeps the placeholders of every message in its translation', () => {
    expect(localizer.validateTranslations().errors).toEqual([]);
  });

  it('has no translation left of a message that is gone from the source (run npm run i18n:extract)', () => {
    const current = new Set(localizer.extractSourceMessages().messages.map((message) => message.name));
    const stale = (localizer.readTranslationsSync().translations.get(TARGET) ?? []).filter((message) => !current.has(message.name)).map(text);
    expect(stale).toEqual([]);
  });

  it('is the XLIFF file that extraction writes (run npm run i18n:extract)', async () => {
    await localizer.writeInterchangeFiles();
    expect(readFileSync(join(folder, 'xliff', `${TARGET}.xlf`), 'utf8')).toBe(readFileSync(join(root, 'xliff', `${TARGET}.xlf`), 'utf8'));
  });

  it('is built into the committed module the app loads (run npm run i18n:build)', async () => {
    await localizer.build();
    const committed = (file: string) => readFileSync(join(root, 'src', 'locales', file), 'utf8');
    expect(readFileSync(join(folder, 'locales', 'locale-codes.ts'), 'utf8')).toBe(committed('locale-codes.ts'));
    // The catalogue as the app loads it: split into the first screen's messages and the later parts'.
    const { first, later } = splitDutchCatalogue(localizer, readFileSync(join(folder, 'locales', `${TARGET}.ts`), 'utf8'));
    expect(first, `${TARGET}.ts`).toBe(committed(`${TARGET}.ts`));
    expect(later, `${TARGET}-later.ts`).toBe(committed(`${TARGET}-later.ts`));
  });
});
