from plans.cli.common import main

raise SystemExit(main())
