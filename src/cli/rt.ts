/**
 * The `rt` command (spec §4): the ray tracer without a browser. Every failure ends in one
 * clear message on stderr and exit code 1 (invalid input) or 2 (wrong usage), never a stack
 * trace.
 */
import { EXIT_INVALID_INPUT, EXIT_USAGE, UsageError } from './cli-errors.ts';
import { CommandLine, type Command } from './command-line.ts';
import { prestartRenderWorker } from './render-worker-thread.ts';

/**
 * Each command is loaded only when it is run: `rt render` then never loads the tracer in
 * its main thread (only its workers do), which keeps its start-up short. Its first worker
 * thread starts before the command's modules load, so that the two start-ups overlap.
 */
const COMMANDS: Record<string, () => Promise<Command>> = {
  render: async () => {
    prestartRenderWorker();
    return (await import('./render-command.ts')).renderCommand;
  },
  trace: async () => (await import('./trace-command.ts')).traceCommand,
  validate: async () => (await import('./validate-command.ts')).validateCommand,
};

const HELP = `rt: Ray Tracer Quest's ray tracer on the command line

Usage:
  rt render <scene.json|level-id> --out <file.png> [--width W] [--height H] [--workers N] [--seed S] [--stats]
  rt trace <scene.json|level-id> --pixel X,Y
  rt validate <file.json>...

Run "rt <command> --help" for one command.
Exit codes: 0 done, 1 invalid input or a failed render, 2 wrong usage.
`;

async function rt(args: string[]): Promise<number> {
  const [name, ...rest] = args;
  if (name === '--help' || name === '-h' || name === 'help') {
    process.stdout.write(HELP);
    return 0;
  }
  if (name === undefined) throw new UsageError('', 'no command given');
  if (!Object.hasOwn(COMMANDS, name)) throw new UsageError('', `unknown command "${name}"`);
  const command = await COMMANDS[name]();
  const line = new CommandLine(name, rest, command);
  if (line.help) {
    process.stdout.write(command.help);
    return 0;
  }
  return command.run(line);
}

function report(error: unknown): number {
  if (error instanceof UsageError) {
    const command = error.command ? `rt ${error.command}` : 'rt';
    process.stderr.write(`${command}: ${error.message} (see "${command} --help")\n`);
    return EXIT_USAGE;
  }
  const message = error instanceof Error ? error.message : String(error);
  for (const line of message.split('\n')) process.stderr.write(`rt: ${line}\n`);
  return EXIT_INVALID_INPUT;
}

// exitCode, not process.exit(): output still being written to a pipe is not cut off.
process.exitCode = await rt(process.argv.slice(2)).catch(report);
