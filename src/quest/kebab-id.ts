import { z } from 'zod';
import { describeValue } from '../scene/scene-issues.ts';

/** Ids of levels, chapters, tasks and badges: they appear in file names, links and exported logs. */
export const kebabId = () =>
  z.string().regex(/^[a-z0-9]+(-[a-z0-9]+)*$/, {
    error: (issue) => `must be lower-case letters and digits joined by "-", like "rays-from-the-camera", got ${describeValue(issue.input)}`,
  });
