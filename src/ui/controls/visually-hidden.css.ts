import { css } from 'lit';

/**
 * The declarations that hide an element from sight but not from screen readers (the usual
 * clip, so it takes no room): for a rule of a component's own, such as a heading a small
 * screen has no room for.
 */
export const visuallyHidden = css`
  position: absolute;
  width: 1px;
  height: 1px;
  overflow: hidden;
  clip-path: inset(50%);
  white-space: nowrap;
`;

/** `.visually-hidden`: read out by screen readers, not shown. */
export const visuallyHiddenStyles = css`
  .visually-hidden {
    ${visuallyHidden}
  }
`;
