"""Drake (optional extra ``[drake]``): the loader, the state map to canonical coordinates, the adapter."""
