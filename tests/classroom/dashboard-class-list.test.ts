import { describe, expect, it } from 'vitest';
import { readClassFiles } from '../../src/classroom/dashboard-class.ts';
import { checkClassList, parseClassList } from '../../src/classroom/dashboard-class-list.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import { simulatedExport } from '../support/class-exports.ts';

/** A learner's results file with the code they typed. */
function fileOf(index: number, participant: string) {
  const file = { ...simulatedExport(index), participant, learner: { ...simulatedExport(index).learner, id: participant } };
  return { name: `ray-tracer-quest-${participant}.json`, text: JSON.stringify(file) };
}

describe('class list', () => {
  it('reads one code per line, trimmed, without empty lines, each code once whatever its case', () => {
    expect(parseClassList(' 5H2-01 \r\n\n5H2-02\n5h2-01\n\t5H2-03\n')).toEqual(['5H2-01', '5H2-02', '5H2-03']);
    expect(parseClassList('\n  \n')).toEqual([]);
  });

  it('says who handed in, who is missing and whose code is not on the list', () => {
    // 5H2-02 typed their code in lower case (the dashboard reads it as the code it is); 5H2-09 is not on the list; nobody handed in 5H2-03.
    const files = [fileOf(0, '5H2-01'), fileOf(1, '5h2-02 '), fileOf(2, '5H2-09')];
    const learners = classLearners(readClassFiles(files).records);
    const check = checkClassList(parseClassList('5H2-01\n5H2-02\n5H2-03'), learners);
    expect(check.handedIn.map(({ code, learners: found }) => [code, found.map((learner) => learner.participant)])).toEqual([
      ['5H2-01', ['5H2-01']],
      ['5H2-02', ['5H2-02']],
    ]);
    expect(check.missing).toEqual(['5H2-03']);
    expect(check.notOnList.map((learner) => [learner.participant, learner.files])).toEqual([['5H2-09', ['ray-tracer-quest-5H2-09.json']]]);
  });

  it('counts a code typed in two cases as one learner', () => {
    // One pupil, two playthroughs: once as "5h2-04", after "start again" as "5H2-04".
    const first = simulatedExport(3);
    const second = simulatedExport(4);
    const files = [
      { name: 'a.json', text: JSON.stringify({ ...first, participant: '5h2-04', learner: { ...first.learner, id: '5h2-04' } }) },
      { name: 'b.json', text: JSON.stringify({ ...second, participant: '5H2-04', learner: { ...second.learner, id: '5H2-04' } }) },
    ];
    const learners = classLearners(readClassFiles(files).records);
    expect(learners).toHaveLength(1);
    expect(learners[0].files).toEqual(['a.json', 'b.json']);
    expect(checkClassList(['5H2-04'], learners).missing).toEqual([]);
  });
});
