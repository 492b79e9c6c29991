"""What each command shows: its table columns, its JSON/CSV keys, its cells' text and its footers, one module a command.

A command module in ``camtool/cli/`` declares options and calls its plan; what its rows look like —
the columns a table shows, their kinds and the keys scripts get — is declared here, beside the
renderers that draw them (``tests/test_readme_keys.py`` checks the README against these keys).
"""
