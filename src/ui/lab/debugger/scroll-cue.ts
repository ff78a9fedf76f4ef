import { css } from 'lit';

/**
 * A soft shadow at the edge of a scrolling list where more rows lie beyond it, so that a
 * learner sees that the pseudocode, the rays or the terms go on below (or above) the short
 * dock; headless and overlay scrollbars show nothing until scrolled. CSS only ("scrolling
 * shadows", Lea Verou 2012): two covers in the list's own colour scroll with its rows and hide
 * the two fixed shadows when the list is at that end. The element sets `--cue-bg` to the colour
 * behind its rows. Declarations to put in the scrolling element's rule.
 */
export const scrollCue = css`
  --cue-shadow: color-mix(in srgb, var(--rt-text) 28%, transparent);
  background:
    linear-gradient(var(--cue-bg) 30%, transparent) center top / 100% 28px no-repeat local,
    linear-gradient(transparent, var(--cue-bg) 70%) center bottom / 100% 28px no-repeat local,
    radial-gradient(farthest-side at 50% 0, var(--cue-shadow), transparent) center top / 100% 9px no-repeat scroll,
    radial-gradient(farthest-side at 50% 100%, var(--cue-shadow), transparent) center bottom / 100% 9px no-repeat scroll,
    var(--cue-bg);
`;
