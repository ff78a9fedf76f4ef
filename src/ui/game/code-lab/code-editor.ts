import { javascript } from '@codemirror/lang-javascript';
import { syntaxHighlighting, syntaxTree } from '@codemirror/language';
import { linter, lintGutter, type Diagnostic } from '@codemirror/lint';
import { basicSetup, EditorView } from 'codemirror';
import { codeHighlightStyle } from './code-highlight.ts';

/**
 * The code lab's editor: CodeMirror 6 with its basic setup (line numbers, JavaScript
 * highlighting, bracket matching, undo, search), syntax errors marked at their line as the
 * learner types, before anything runs. Tab is left to move focus out of the editor (the
 * keyboard user is never trapped); Escape then Tab does the same in CodeMirror's own way.
 */
export function createCodeEditor(options: {
  parent: HTMLElement;
  doc: string;
  label: string;
  syntaxError: string;
  onChange: (code: string) => void;
}): EditorView {
  return new EditorView({
    doc: options.doc,
    parent: options.parent,
    extensions: [
      basicSetup,
      javascript(),
      // basicSetup's default style is only a fallback, so this one replaces it: readable in the dark theme too.
      syntaxHighlighting(codeHighlightStyle),
      lintGutter(),
      // The editor sits in the task column, about 250 px wide: long lines and the skeleton's
      // step comments wrap instead of hiding past a sideways scroll.
      EditorView.lineWrapping,
      linter((view) => syntaxErrors(view, options.syntaxError), { delay: 300 }),
      // The code area is reached by Tab as any editable element is; the explicit tabindex also
      // tells accessibility checkers (axe's scrollable-region-focusable) that the scrolling box
      // around it holds focusable content, which they do not infer from contenteditable.
      EditorView.contentAttributes.of({ 'aria-label': options.label, tabindex: '0' }),
      EditorView.updateListener.of((update) => {
        if (update.docChanged) options.onChange(update.state.doc.toString());
      }),
    ],
  });
}

/** The parser's error nodes, each a diagnostic at its place: what the browser would refuse to run. */
function syntaxErrors(view: EditorView, message: string): Diagnostic[] {
  const found: Diagnostic[] = [];
  syntaxTree(view.state).iterate({
    enter: (node) => {
      if (!node.type.isError) return;
      const from = node.from;
      const to = Math.min(Math.max(node.to, from + 1), view.state.doc.length);
      found.push({ from: Math.min(from, to), to, severity: 'error', message });
    },
  });
  return found;
}

/** Replaces the editor's whole text (Reset to the skeleton). */
export function replaceCode(view: EditorView, code: string): void {
  view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: code } });
}
