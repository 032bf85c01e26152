"""The run: models and their labels, poses, chunks, engine runs, records and summaries, at any scale."""
