/** `rt validate`: checks scene and level files and lists every problem (spec §4). */
import { EXIT_INVALID_INPUT } from './cli-errors.ts';
import type { Command } from './command-line.ts';
import { checkSceneFile } from './scene-file.ts';

export const validateCommand: Command = {
  help: `Usage: rt validate <file.json>...

Checks scene files and level files (a level's "scene" is checked). Prints "<file>: ok" for a
valid file and every problem as "<file>: <path>: <reason>"; exits 1 if any file has a problem.

Options:
  -h, --help        show this text
`,
  async run(line) {
    if (line.positionals.length === 0) throw line.usageError('give one or more files to check');
    let allValid = true;
    for (const file of line.positionals) {
      const check = await checkSceneFile(file);
      if (check.ok) {
        process.stdout.write(`${file}: ok\n`);
      } else {
        allValid = false;
        for (const problem of check.problems) process.stderr.write(`${file}: ${problem}\n`);
      }
    }
    return allValid ? 0 : EXIT_INVALID_INPUT;
  },
};
