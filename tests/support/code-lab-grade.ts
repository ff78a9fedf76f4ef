import { gradeLab, type LabCase, type LabOutcome, type LabReport, type Tolerance } from '../../src/quest/code-labs/code-lab-grading.ts';

/** Runs a learner's function on every case here, as the sandbox does in the browser (a structured copy of the answer), and grades the run. */
export function gradeFunction(cases: LabCase[], tolerance: Tolerance, learner: (...args: never[]) => unknown): LabReport {
  const outcomes = cases.map((labCase): LabOutcome => {
    try {
      return { returned: structuredClone(learner(...(structuredClone(labCase.args) as never[]))) };
    } catch (error) {
      return { threw: String(error), line: null };
    }
  });
  return gradeLab(cases, outcomes, tolerance);
}
