/**
 * One `path: reason` line for text that is not JSON, e.g.
 * `(root): not valid JSON at line 3, column 7: expected a value, found "}"`.
 *
 * We find the place ourselves because the engines do not agree: V8 gives no position for an
 * unexpected token, Safari none at all. This runs only after JSON.parse has failed, so it
 * only has to find where the text stops being JSON, not build anything.
 */
export function describeJsonError(text: string): string {
  const problem = findJsonProblem(text);
  const { line, column } = placeOfOffset(text, problem.offset);
  const found = problem.offset < text.length ? JSON.stringify(text[problem.offset]) : 'the end of the text';
  return `(root): not valid JSON at line ${line}, column ${column}: expected ${problem.expected}, found ${found}`;
}

interface JsonProblem {
  offset: number;
  expected: string;
}

/** Scans JSON's grammar (RFC 8259) and stops at the first character that does not fit. */
function findJsonProblem(text: string): JsonProblem {
  let offset = 0;
  const fail = (expected: string): JsonProblem => ({ offset, expected });
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
    if (!NUMBER.test(text)) return fail('a value');
    offset = NUMBER.lastIndex;
    return undefined;
  };

  const readContainer = (close: string, isObject: boolean): JsonProblem | undefined => {
    offset++;
    skipWhitespace();
    if (text[offset] === close) {
      offset++;
      return undefined;
    }
    for (;;) {
      if (isObject) {
        skipWhitespace();
        if (text[offset] !== '"') return fail('a field name in double quotes');
        const nameProblem = readString();
        if (nameProblem) return nameProblem;
        skipWhitespace();
        if (text[offset] !== ':') return fail('":"');
        offset++;
      }
      const valueProblem = readValue();
      if (valueProblem) return valueProblem;
      skipWhitespace();
      if (text[offset] === close) {
        offset++;
        return undefined;
      }
      if (text[offset] !== ',') return fail(`"," or "${close}"`);
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
      if (char < ' ') return fail("a closing '\"' (write a line break inside a string as \\n)");
      if (char === '\\') {
        ESCAPE.lastIndex = offset;
        if (!ESCAPE.test(text)) return fail('an escape such as \\n, \\" or \\u00e9');
        offset = ESCAPE.lastIndex;
      } else {
        offset++;
      }
    }
    return fail("a closing '\"'");
  };

  try {
    const problem = readValue();
    skipWhitespace();
    return problem ?? fail('the end of the text');
  } catch {
    // Only nesting deep enough to exhaust the stack gets here; point at where we were.
    return fail('less deeply nested lists and objects');
  }
}

const NUMBER = /-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?/y;
const ESCAPE = /\\(["\\/bfnrt]|u[0-9a-fA-F]{4})/y;

/** 1-based line and column of a character offset. */
function placeOfOffset(text: string, offset: number): { line: number; column: number } {
  const before = text.slice(0, offset);
  return { line: before.split('\n').length, column: offset - (before.lastIndexOf('\n') + 1) + 1 };
}
