// The app's entry point: registers the elements; they do the rest when they connect.
import './ui/shell/rt-app.ts';
