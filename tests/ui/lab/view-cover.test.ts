import { describe, expect, it } from 'vitest';
import { coveredBottom } from '../../../src/ui/lab/view-cover.ts';

const rect = (left: number, top: number, width: number, height: number) => ({ left, top, width, height, right: left + width, bottom: top + height });

describe('how much of the 3D view panels cover from below', () => {
  const view = rect(300, 45, 786, 723);

  it("counts an overlay in the lower part of the view to the view's bottom", () => {
    expect(coveredBottom(view, [rect(308, 480, 352, 280)])).toBe(768 - 480);
  });

  it('takes the tallest, and leaves out overlays at the top, beside the view or with no size', () => {
    expect(
      coveredBottom(view, [rect(308, 600, 352, 160), rect(308, 420, 770, 340), rect(944, 105, 134, 32), rect(1100, 500, 200, 200), rect(400, 500, 0, 0)]),
    ).toBe(768 - 420);
    expect(coveredBottom(view, [])).toBe(0);
  });
});
