/** A render worker whose module fails as it loads, for testing a thread that dies before any pool uses it. */
throw new Error('the test worker failed to start on purpose');
