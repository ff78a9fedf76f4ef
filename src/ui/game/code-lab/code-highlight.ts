import { HighlightStyle } from '@codemirror/language';
import { tags } from '@lezer/highlight';

/**
 * The editor's JavaScript colours in both themes: CodeMirror's default highlight style has
 * one set, made for a white page, whose purple and blue keep 1.7:1 and 1.9:1 on the dark
 * theme's surface. Each colour here is light-dark(CodeMirror's own, a light tint of it), the
 * tints at 6:1 or more on the dark surface (#1a2029), so every kind of token stays readable
 * (WCAG 1.4.3, 4.5:1).
 */
export const codeHighlightStyle = HighlightStyle.define([
  { tag: tags.meta, color: 'light-dark(#404740, #b8c2b8)' },
  { tag: tags.link, textDecoration: 'underline' },
  { tag: tags.heading, textDecoration: 'underline', fontWeight: 'bold' },
  { tag: tags.emphasis, fontStyle: 'italic' },
  { tag: tags.strong, fontWeight: 'bold' },
  { tag: tags.strikethrough, textDecoration: 'line-through' },
  { tag: tags.keyword, color: 'light-dark(#708, #d7a8f0)' },
  { tag: [tags.atom, tags.bool, tags.url, tags.contentSeparator, tags.labelName], color: 'light-dark(#219, #a9b8ff)' },
  { tag: [tags.literal, tags.inserted], color: 'light-dark(#164, #8fd9a8)' },
  { tag: [tags.string, tags.deleted], color: 'light-dark(#a11, #ffa8a0)' },
  { tag: [tags.regexp, tags.escape, tags.special(tags.string)], color: 'light-dark(#e40, #ffb480)' },
  { tag: tags.definition(tags.variableName), color: 'light-dark(#00f, #9cc0ff)' },
  { tag: tags.local(tags.variableName), color: 'light-dark(#30a, #c0b0ff)' },
  { tag: [tags.typeName, tags.namespace], color: 'light-dark(#085, #80d8b8)' },
  { tag: tags.className, color: 'light-dark(#167, #8ad4e0)' },
  { tag: [tags.special(tags.variableName), tags.macroName], color: 'light-dark(#256, #a0c8d8)' },
  { tag: tags.definition(tags.propertyName), color: 'light-dark(#00c, #9cc0ff)' },
  { tag: tags.comment, color: 'light-dark(#940, #e0b070)' },
  { tag: tags.invalid, color: 'light-dark(#f00, #ff8a80)' },
]);
