/** A command of `rt` and the reading of its arguments (node:util parseArgs), with usage errors in plain words. */
import { parseArgs } from 'node:util';
import { UsageError } from './cli-errors.ts';

/** A negative number such as -5 or -0.5, which is a value, not an option. */
const NEGATIVE_NUMBER = /^-\.?\d/;

export interface Command {
  /** Options that take a value (`--out x.png`). */
  strings?: string[];
  /** Switches (`--stats`). */
  flags?: string[];
  /** Printed for `--help`. */
  help: string;
  /** Returns the exit code; throws UsageError or InputError for bad input. */
  run(line: CommandLine): Promise<number>;
}

export class CommandLine {
  readonly positionals: string[];
  /** -h or --help was given. */
  readonly help: boolean;
  private readonly values: Record<string, string | boolean | (string | boolean)[] | undefined>;

  constructor(
    readonly command: string,
    args: string[],
    { strings = [], flags = [] }: Pick<Command, 'strings' | 'flags'>,
  ) {
    const options = Object.fromEntries([
      ...strings.map((name) => [name, { type: 'string' as const }]),
      ...flags.map((name) => [name, { type: 'boolean' as const }]),
      ['help', { type: 'boolean' as const, short: 'h' }],
    ]);
    // Not strict: parseArgs' own messages are long and suggest `--`; the checks below say it shorter.
    const { values, positionals, tokens } = parseArgs({ args, options, allowPositionals: true, strict: false, tokens: true });
    for (const token of tokens) {
      if (token.kind !== 'option') continue;
      const { name, rawName, value, inlineValue } = token;
      // hasOwn, not `in`: --constructor or --toString must not pass as options of every command.
      if (!Object.hasOwn(options, name)) throw this.usageError(`unknown option ${rawName}`);
      const takesValue = strings.includes(name);
      // A value starting with "-" is the next option, unless it reads as a negative number
      // (--width -5), which is then refused by its own range check with the value named.
      if (takesValue && (value === undefined || (!inlineValue && value.startsWith('-') && !NEGATIVE_NUMBER.test(value)))) {
        throw this.usageError(`${rawName} needs a value`);
      }
      if (!takesValue && value !== undefined) throw this.usageError(`${rawName} takes no value`);
    }
    this.positionals = positionals;
    this.help = values.help === true;
    this.values = values;
  }

  usageError(message: string): UsageError {
    return new UsageError(this.command, message);
  }

  /** The only positional argument; a UsageError asking for `what` otherwise. */
  onePositional(what: string): string {
    if (this.positionals.length !== 1) throw this.usageError(`give exactly one ${what}`);
    return this.positionals[0];
  }

  /** The value of a string option, or undefined when it was not given. */
  text(name: string): string | undefined {
    const value = this.values[name];
    return typeof value === 'string' ? value : undefined;
  }

  /** The value of a string option that must be given, e.g. `requiredText('out', '<file.png>')`. */
  requiredText(name: string, placeholder: string): string {
    const value = this.text(name);
    if (value === undefined) throw this.usageError(`missing --${name} ${placeholder}`);
    return value;
  }

  flag(name: string): boolean {
    return this.values[name] === true;
  }

  /** A string option as a whole number in [lowest, highest], or undefined when it was not given. */
  wholeNumber(name: string, [lowest, highest]: readonly [number, number]): number | undefined {
    const text = this.text(name);
    if (text === undefined) return undefined;
    const value = Number(text);
    if (!/^\s*-?\d+\s*$/.test(text) || value < lowest || value > highest) {
      throw this.usageError(`--${name} must be a whole number from ${lowest} to ${highest}, got "${text}"`);
    }
    return value;
  }
}
