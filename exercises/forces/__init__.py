"""The force analysis's files and sweeps: a linkage's loads read from its file, and the
turning-moment diagram over a turn. Its exercises are the linkages' (their chapter)."""
