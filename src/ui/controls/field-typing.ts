import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { StatusMessage } from './status-message.ts';

/** What typed text means: a value to commit (or none), and a note for the message line. */
export interface TypedReading<T> {
  value?: T;
  note?: string;
}

/** What a host with typed fields tells the controller. */
export interface FieldTypingOptions<T> {
  /** Reads the text of field `index`, with the host's current properties. */
  read(text: string, index: number): TypedReading<T>;
  /** Called with the accepted value of field `index`. */
  commit(value: T, index: number): void;
}

/**
 * Text fields that commit a value (rt-slider's number, rt-vector-field's components,
 * rt-color-field's hex code): keeps what is being typed through re-renders, commits on
 * Enter or on leaving the field, reverts on Escape, and puts the note about the text in
 * the host's message line (a problem when nothing could be read, info otherwise).
 */
export class FieldTyping<T> implements ReactiveController {
  readonly message: StatusMessage;
  private readonly typed = new Map<number, string>();

  constructor(
    private readonly host: ReactiveControllerHost,
    private readonly options: FieldTypingOptions<T>,
  ) {
    host.addController(this);
    this.message = new StatusMessage(host);
  }

  hostDisconnected(): void {
    this.typed.clear();
  }

  /** What field `index` shows: the text being typed, or else `shown` (the owner's value). */
  text(index: number, shown: string): string {
    return this.typed.get(index) ?? shown;
  }

  /** Forgets typing (dragging the slider replaces it). */
  reset(): void {
    this.typed.clear();
  }

  /** For the field's native `input` event, which is composed and would otherwise reach the owner. */
  input(index: number, event: Event): void {
    event.stopPropagation();
    this.typed.set(index, (event.target as HTMLInputElement).value);
  }

  /** For the field's native `change` (leaving it) and for Enter: reads and commits the text. */
  change(index: number): void {
    const text = this.typed.get(index);
    if (text === undefined) return;
    this.typed.delete(index);
    const { value, note } = this.options.read(text, index);
    this.message.show(note, value === undefined);
    if (value !== undefined) this.options.commit(value, index);
    // Show the owner's value: the old one when the text was refused, by us or by it.
    this.host.requestUpdate();
  }

  keydown(index: number, event: KeyboardEvent): void {
    if (event.key === 'Enter') this.change(index);
    if (event.key === 'Escape' && this.typed.has(index)) {
      event.stopPropagation();
      this.typed.delete(index);
      this.host.requestUpdate();
    }
  }
}
