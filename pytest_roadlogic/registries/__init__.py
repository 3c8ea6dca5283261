"""The registries the options are made from: every oracle as a record (``oracles``) and the
reference drivers by name (``drivers``). Plain data at the ground floor: the run settings read
them in every pytest session, so they import nothing of the pipeline."""
