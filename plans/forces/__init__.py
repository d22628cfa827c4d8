"""Force analysis (kinetostatics by force plans, Zhukovsky's lever): to come."""
