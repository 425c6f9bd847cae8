"""rtlab's grader: the one engine behind ./lab grade (a student's own work), ./lab grade-class
(a whole class, each student in a sandbox) and the golden-image tests of ./lab test."""
