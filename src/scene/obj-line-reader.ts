const SPACE = 32;
const HASH = 35;
const PLUS = 43;
const MINUS = 45;
const DOT = 46;
const SLASH = 47;
const DIGIT_0 = 48;
const DIGIT_9 = 57;
const BYTE_ORDER_MARK = 0xfeff;

/** Exact powers of ten for the fast decimal path (10^k is exact as a double up to k = 22). */
const POWERS_OF_TEN = Array.from({ length: 16 }, (_, k) => 10 ** k);
/** More significant digits than this might not fit a double's 53-bit integer exactly. */
const MAX_FAST_DIGITS = 15;

function isDigit(code: number): boolean {
  return code >= DIGIT_0 && code <= DIGIT_9;
}

/** Space, tab, CR, vertical tab, form feed and a byte-order mark all separate words. */
function isSpace(code: number): boolean {
  return code === SPACE || (code >= 9 && code <= 13) || code === BYTE_ORDER_MARK;
}

/**
 * Walks an OBJ text line by line and word by word, reading numbers straight from the
 * characters: splitting a 10,000-line file into line and word strings first would cost
 * more than the parsing itself. A `#` ends a line's words (a comment).
 */
export class ObjLineReader {
  /** 1-based number of the current line, for error messages. */
  lineNumber = 0;
  private position = 0;
  private lineEnd = -1;
  /** Where the word that number() or faceCorner() read last begins. */
  private lastWordStart = 0;

  constructor(private readonly text: string) {}

  /** Moves to the start of the next line; false when the text is used up. */
  nextLine(): boolean {
    if (this.lineEnd >= this.text.length) return false;
    this.position = this.lineEnd + 1;
    const newline = this.text.indexOf('\n', this.position);
    this.lineEnd = newline < 0 ? this.text.length : newline;
    this.lineNumber++;
    return true;
  }

  /** Skips spaces; true when another word follows on this line. */
  hasWord(): boolean {
    while (this.position < this.lineEnd && isSpace(this.text.charCodeAt(this.position))) this.position++;
    return this.position < this.lineEnd && this.text.charCodeAt(this.position) !== HASH;
  }

  /** The next word, or '' at the end of the line. */
  word(): string {
    if (!this.hasWord()) return '';
    const start = this.position;
    this.position = this.wordEnd(start);
    return this.text.slice(start, this.position);
  }

  /**
   * The next word as a number, NaN when it is not one (or missing).
   * The usual `-12.345` form is computed here; exponents and long mantissas go to Number().
   * Both give the correctly rounded double: a mantissa of at most 15 digits and a power of
   * ten up to 10^15 are exact, and one division rounds once.
   */
  number(): number {
    if (!this.hasWord()) return NaN;
    const start = this.position;
    this.lastWordStart = start;
    let i = start;
    let code = this.text.charCodeAt(i);
    const negative = code === MINUS;
    if (code === MINUS || code === PLUS) code = this.text.charCodeAt(++i);
    let mantissa = 0;
    let digits = 0;
    let fractionDigits = -1; // -1 until the decimal point
    for (; ; code = this.text.charCodeAt(++i)) {
      if (isDigit(code)) {
        mantissa = mantissa * 10 + (code - DIGIT_0);
        digits++;
        if (fractionDigits >= 0) fractionDigits++;
      } else if (code === DOT && fractionDigits < 0) {
        fractionDigits = 0;
      } else {
        break;
      }
    }
    const end = this.wordEnd(i);
    this.position = end;
    if (i === end && digits > 0 && digits <= MAX_FAST_DIGITS) {
      const value = mantissa / POWERS_OF_TEN[Math.max(fractionDigits, 0)];
      return negative ? -value : value;
    }
    return Number(this.text.slice(start, end));
  }

  /**
   * Reads the face corner `v`, `v/vt`, `v//vn` or `v/vt/vn` that hasWord() found into
   * `corner` (vt is skipped; a missing normal is NaN). False when the word has another form.
   */
  faceCorner(corner: { vertex: number; normal: number }): boolean {
    this.lastWordStart = this.position;
    corner.vertex = this.integer();
    corner.normal = NaN;
    if (this.text.charCodeAt(this.position) === SLASH) {
      this.position++;
      this.integer(); // the texture coordinate, if any
      if (this.text.charCodeAt(this.position) === SLASH) {
        this.position++;
        corner.normal = this.integer();
      }
    }
    return !Number.isNaN(corner.vertex) && this.wordEnd(this.position) === this.position;
  }

  /** The word that number() or faceCorner() read last, for error messages. */
  lastWord(): string {
    return this.text.slice(this.lastWordStart, this.wordEnd(this.lastWordStart));
  }

  /** An optionally negative whole number at the cursor, NaN when there are no digits. */
  private integer(): number {
    let i = this.position;
    const negative = this.text.charCodeAt(i) === MINUS;
    if (negative) i++;
    let value = 0;
    const firstDigit = i;
    for (let code = this.text.charCodeAt(i); isDigit(code); code = this.text.charCodeAt(++i)) {
      value = value * 10 + (code - DIGIT_0);
    }
    if (i === firstDigit) return NaN;
    this.position = i;
    return negative ? -value : value;
  }

  /** Where the word containing `from` ends: at a space, a `#` or the end of the line. */
  private wordEnd(from: number): number {
    let i = from;
    while (i < this.lineEnd) {
      const code = this.text.charCodeAt(i);
      if (isSpace(code) || code === HASH) break;
      i++;
    }
    return i;
  }
}
