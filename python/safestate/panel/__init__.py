"""The operator panel (issue 16): the web page served by the operator link's bridge."""
