import { issueLine, type Issue, type JsonExpected } from './issue.ts';

/**
 * Why a text is not JSON, as an issue (src/util/issue.ts); in English, e.g.
 * `(root): not valid JSON at line 3, column 7: expected a value, found "}"`.
 *
 * We find the place ourselves because the engines do not agree: V8 gives no position for an
 * unexpected token, Safari none at all. This runs only after JSON.parse has failed, so it
 * only has to find where the text stops being JSON, not build anything.
 */
export function jsonIssue(text: string): Issue {
  const problem = findJsonProblem(text);
  const { line, column } = placeOfOffset(text, problem.offset);
  const found = problem.offset < text.length ? text[problem.offset]! : null;
  return { path: '(root)', reason: { code: 'notJson', line, column, expected: problem.expected, found } };
}

/** `jsonIssue` as the English line `rt validate` prints. */
export function describeJsonError(text: string): string {
  return issueLine(jsonIssue(text));
}

interface JsonProblem {
  offset: number;
  expected: JsonExpected;
}

/** Scans JSON's grammar (RFC 8259) and stops at the first character that does not fit. */
function findJsonProblem(text: string): JsonProblem {
  let offset = 0;
  const fail = (expected: JsonExpected): JsonProblem => ({ offset, expected });
  const skipWhitespace = () => {
    while (offset < text.length && ' \t\n\r'.includes(text[offset])) offset++;
  };

  // Each reader moves `offset` past what it read and returns a problem, or undefined when all is well.
  const readValue = (): JsonProblem | undefined => {
    skipWhitespace();
    const char = text[offset];
    if (char === '{') return readContainer('}', true);
    if (char === '[') return readContainer(']', false);
    if (char === '"') return readString();
    for (const word of ['true', 'false', 'null']) {
      if (text.startsWith(word, offset)) {
        offset += word.length;
        return undefined;
      }
    }
    NUMBER.lastIndex = offset;
    if (!NUMBER.test(text)) return fail({ kind: 'value' });
    offset = NUMBER.lastIndex;
    return undefined;
  };

  const readContainer = (close: '}' | ']', isObject: boolean): JsonProblem | undefined => {
    offset++;
    skipWhitespace();
    if (text[offset] === close) {
      offset++;
      return undefined;
    }
    for (;;) {
      if (isObject) {
        skipWhitespace();
        if (text[offset] !== '"') return fail({ kind: 'field name' });
        const nameProblem = readString();
        if (nameProblem) return nameProblem;
        skipWhitespace();
        if (text[offset] !== ':') return fail({ kind: 'colon' });
        offset++;
      }
      const valueProblem = readValue();
      if (valueProblem) return valueProblem;
      skipWhitespace();
      if (text[offset] === close) {
        offset++;
        return undefined;
      }
      if (text[offset] !== ',') return fail({ kind: 'comma or close', close });
      offset++;
    }
  };

  const readString = (): JsonProblem | undefined => {
    offset++;
    while (offset < text.length) {
      const char = text[offset];
      if (char === '"') {
        offset++;
        return undefined;
      }
      if (char < ' ') return fail({ kind: 'closing quote, no line break' });
      if (char === '\\') {
        ESCAPE.lastIndex = offset;
        if (!ESCAPE.test(text)) return fail({ kind: 'escape' });
        offset = ESCAPE.lastIndex;
      } else {
        offset++;
      }
    }
    return fail({ kind: 'closing quote' });
  };

  try {
    const problem = readValue();
    skipWhitespace();
    return problem ?? fail({ kind: 'end of text' });
  } catch {
    // Only nesting deep enough to exhaust the stack gets here; point at where we were.
    return fail({ kind: 'less nesting' });
  }
}

const NUMBER = /-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?/y;
const ESCAPE = /\\(["\\/bfnrt]|u[0-9a-fA-F]{4})/y;

/** 1-based line and column of a character offset. */
function placeOfOffset(text: string, offset: number): { line: number; column: number } {
  const before = text.slice(0, offset);
  return { line: before.split('\n').length, column: offset - (before.lastIndexOf('\n') + 1) + 1 };
}
