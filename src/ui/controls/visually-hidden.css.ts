import { css } from 'lit';

/** `.visually-hidden`: read out by screen readers, not shown (the usual clip, so it takes no room). */
export const visuallyHiddenStyles = css`
  .visually-hidden {
    position: absolute;
    width: 1px;
    height: 1px;
    overflow: hidden;
    clip-path: inset(50%);
    white-space: nowrap;
  }
`;
