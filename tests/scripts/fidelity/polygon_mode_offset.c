/* piglit general/polygon-mode-offset: seven configurations, each in its own 64x64 viewport
   of a 448x64 window (config i at x = 64i), that must all show a blue fill with a white
   outline one pixel inside the viewport's edges: separate front/back polygon modes, CW/CCW
   winding, OFFSET_FILL (1, 1) or OFFSET_LINE (1, -1), DepthFunc LEQUAL, modelview
   translated by (0.375, 0.375) so lines hit pixel centres. Blue covers [0, 64]^2, white
   outlines [1, 62]^2. */
glClearColor(1, 0, 0, 0);
glEnable(GL_DEPTH_TEST);
glDepthFunc(GL_LEQUAL);
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 64, 0, 64, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glTranslatef(0.375f, 0.375f, 0);
/* config 0 */
glViewport(0, 0, 64, 64);
glEnable(GL_POLYGON_OFFSET_FILL);
glPolygonOffset(1, 1);
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_LINE);
glColor3f(1, 1, 1);
glBegin(GL_POLYGON);
glVertex2f(1, 1); glVertex2f(62, 1); glVertex2f(62, 62); glVertex2f(1, 62);
glEnd();
glPolygonMode(GL_FRONT, GL_FILL);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(0, 0, 1);
glBegin(GL_POLYGON);
glVertex2f(0, 0); glVertex2f(64, 0); glVertex2f(64, 64); glVertex2f(0, 64);
glEnd();
glDisable(GL_POLYGON_OFFSET_FILL);
/* config 1 */
glViewport(64, 0, 64, 64);
glEnable(GL_POLYGON_OFFSET_FILL);
glPolygonOffset(1, 1);
glPolygonMode(GL_FRONT, GL_FILL);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(0, 0, 1);
glBegin(GL_POLYGON);
glVertex2f(0, 0); glVertex2f(64, 0); glVertex2f(64, 64); glVertex2f(0, 64);
glEnd();
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_LINE);
glColor3f(1, 1, 1);
glBegin(GL_POLYGON);
glVertex2f(1, 1); glVertex2f(62, 1); glVertex2f(62, 62); glVertex2f(1, 62);
glEnd();
glDisable(GL_POLYGON_OFFSET_FILL);
/* config 2 */
glViewport(128, 0, 64, 64);
glEnable(GL_POLYGON_OFFSET_FILL);
glPolygonOffset(1, 1);
glPolygonMode(GL_FRONT, GL_FILL);
glPolygonMode(GL_BACK, GL_LINE);
glColor3f(0, 0, 1);
glBegin(GL_POLYGON);
glVertex2f(0, 0); glVertex2f(64, 0); glVertex2f(64, 64); glVertex2f(0, 64);
glEnd();
glPolygonMode(GL_FRONT, GL_FILL);
glPolygonMode(GL_BACK, GL_LINE);
glColor3f(1, 1, 1);
glBegin(GL_POLYGON);
glVertex2f(1, 1); glVertex2f(1, 62); glVertex2f(62, 62); glVertex2f(62, 1);
glEnd();
glDisable(GL_POLYGON_OFFSET_FILL);
/* config 3 */
glViewport(192, 0, 64, 64);
glEnable(GL_POLYGON_OFFSET_FILL);
glPolygonOffset(1, 1);
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(1, 1, 1);
glBegin(GL_POLYGON);
glVertex2f(1, 1); glVertex2f(62, 1); glVertex2f(62, 62); glVertex2f(1, 62);
glEnd();
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(0, 0, 1);
glBegin(GL_POLYGON);
glVertex2f(0, 0); glVertex2f(0, 64); glVertex2f(64, 64); glVertex2f(64, 0);
glEnd();
glDisable(GL_POLYGON_OFFSET_FILL);
/* config 4 */
glViewport(256, 0, 64, 64);
glEnable(GL_POLYGON_OFFSET_LINE);
glPolygonOffset(1, -1);
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(1, 1, 1);
glBegin(GL_POLYGON);
glVertex2f(1, 1); glVertex2f(62, 1); glVertex2f(62, 62); glVertex2f(1, 62);
glEnd();
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(0, 0, 1);
glBegin(GL_POLYGON);
glVertex2f(0, 0); glVertex2f(0, 64); glVertex2f(64, 64); glVertex2f(64, 0);
glEnd();
glDisable(GL_POLYGON_OFFSET_LINE);
/* config 5 */
glViewport(320, 0, 64, 64);
glEnable(GL_POLYGON_OFFSET_LINE);
glPolygonOffset(1, -1);
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(0, 0, 1);
glBegin(GL_POLYGON);
glVertex2f(0, 0); glVertex2f(0, 64); glVertex2f(64, 64); glVertex2f(64, 0);
glEnd();
glPolygonMode(GL_FRONT, GL_LINE);
glPolygonMode(GL_BACK, GL_FILL);
glColor3f(1, 1, 1);
glBegin(GL_POLYGON);
glVertex2f(1, 1); glVertex2f(62, 1); glVertex2f(62, 62); glVertex2f(1, 62);
glEnd();
glDisable(GL_POLYGON_OFFSET_LINE);
/* config 6 */
glViewport(384, 0, 64, 64);
glEnable(GL_POLYGON_OFFSET_LINE);
glPolygonOffset(1, -1);
glPolygonMode(GL_FRONT, GL_FILL);
glPolygonMode(GL_BACK, GL_LINE);
glColor3f(0, 0, 1);
glBegin(GL_POLYGON);
glVertex2f(0, 0); glVertex2f(64, 0); glVertex2f(64, 64); glVertex2f(0, 64);
glEnd();
glPolygonMode(GL_FRONT, GL_FILL);
glPolygonMode(GL_BACK, GL_LINE);
glColor3f(1, 1, 1);
glBegin(GL_POLYGON);
glVertex2f(1, 1); glVertex2f(1, 62); glVertex2f(62, 62); glVertex2f(62, 1);
glEnd();
glDisable(GL_POLYGON_OFFSET_LINE);
