/**
 * The two ways a command can be wrong, and their exit codes (spec §4: bad input gives one
 * clear message and exit code 1 or 2, never a stack trace).
 */

/** Exit code for invalid input: a missing or invalid file, an unwritable output, a failed render. */
export const EXIT_INVALID_INPUT = 1;
/** Exit code for a wrong command line: unknown command or option, missing or malformed value. */
export const EXIT_USAGE = 2;

export class UsageError extends Error {
  /** @param command - The command whose help explains the fix, or '' for `rt --help`. */
  constructor(
    readonly command: string,
    message: string,
  ) {
    super(message);
  }
}

/** Invalid input; the message may have several lines, each a complete statement. */
export class InputError extends Error {}

/** A file system error in a few words, e.g. "no such file or folder". */
export function describeFileError(error: unknown): string {
  const code = error instanceof Error && 'code' in error ? error.code : undefined;
  switch (code) {
    case 'ENOENT':
      return 'no such file or folder';
    case 'EISDIR':
      return 'it is a folder';
    case 'ENOTDIR':
      return 'part of the path is not a folder';
    case 'EACCES':
    case 'EPERM':
      return 'permission denied';
    case 'EROFS':
      return 'the file system is read-only';
    default:
      return error instanceof Error ? error.message : String(error);
  }
}
