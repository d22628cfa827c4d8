from plans.cli.main import main

raise SystemExit(main())
