"""``drafting serve``: a local web app where a scene's text is edited beside its sheets, redrawn as it is
typed (the optional extra ``.[serve]``: starlette, uvicorn, watchfiles).

:mod:`.workspace` holds the files it may read and write (one scene, or the scenes of one folder; saves
atomic with a backup, a version check between tabs); :mod:`.live` turns a scene's text into its step-through
page or its one error sentence with the line and key it names; :mod:`.server` is the web app (a token,
Host and Origin checked on every request); :mod:`.command` starts it and prints its URL.
"""
