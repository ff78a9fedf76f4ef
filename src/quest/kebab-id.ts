import { z } from 'zod';
import { withReason } from '../scene/scene-issues.ts';
import { gotOf } from '../util/issue.ts';
import { LIMITS } from '../scene/scene-limits.ts';

/** As scene ids: long enough for any name, short enough that a message quoting one stays readable. */
export const ID_MAX = LIMITS.idLength[1];

/** Ids of levels, chapters, tasks and badges: they appear in file names, links and exported logs. */
export const kebabId = () =>
  z
    .string()
    .max(ID_MAX)
    .regex(/^[a-z0-9]+(-[a-z0-9]+)*$/, {
      error: (issue) => withReason(issue, { code: 'notKebabId', got: gotOf(issue.input) }),
    });
