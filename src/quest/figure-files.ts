/**
 * The figures a task may show (`figure.src`, docs/levels.md). Each one ships as
 * assets/figures/<name>; adding a figure means adding its file and its name here, so a level
 * that names a figure the app does not have is refused when it loads, with this list
 * (tests/quest/level-figures.test.ts checks the list is the folder's). SVG or PNG: the kinds
 * the offline cache keeps (vite.config.ts).
 */
export const FIGURE_FILES = ['lambert-torch.svg', 'path-noise-error.svg'] as const;

export type FigureFile = (typeof FIGURE_FILES)[number];
