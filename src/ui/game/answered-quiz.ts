/**
 * Which answered quiz stays open in the task list. A quiz's feedback is read just after the
 * answer, while the learner starts the task after it; once that task is done too (the
 * current task moves on again), the quiz folds up like every finished task, so answered
 * quizzes do not pile up above the current task.
 */
export class AnsweredQuiz {
  private quiz: string | null = null;
  /** The current task when the quiz was left: undefined while the quiz is still current. */
  private next: string | null | undefined = undefined;

  /** The learner answered (or was shown) the quiz `task`. */
  answered(task: string): void {
    this.quiz = task;
    this.next = undefined;
  }

  /** Another level: nothing of the last one stays open. */
  clear(): void {
    this.quiz = null;
    this.next = undefined;
  }

  /** Given the task now current (null when none), the quiz to keep open, if any. */
  openFor(current: string | null): string | null {
    if (this.quiz === null || current === this.quiz) return this.quiz;
    if (this.next === undefined) this.next = current;
    else if (current !== this.next) this.clear();
    return this.quiz;
  }
}
