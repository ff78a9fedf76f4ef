import { expect, test } from '@playwright/test';

// The teacher page remembers: an assignment made is kept in the browser and back after a
// reload, copied for another class with the same levels; any level opens as a preview that
// saves nothing; the form's own address reopens it elsewhere.

test('the teacher page keeps its assignments, copies one for another class and previews a level', async ({ page }) => {
  await page.goto('./#/teacher');
  const teacher = page.locator('rt-teacher-page');
  const shelf = teacher.locator('rt-teacher-shelf');
  await teacher.getByRole('textbox', { name: /Title \(the students see it\)/ }).fill('Lesson 1');
  await teacher.getByRole('combobox', { name: 'Add a level' }).selectOption({ label: 'Shadows' });
  await teacher.getByRole('button', { name: 'Add', exact: true }).click();
  await teacher.getByRole('textbox', { name: /Class code \(the dashboard/ }).fill('5H2');
  await expect(shelf.getByRole('status')).toHaveText(/^Kept in this browser/);

  await page.reload();
  await expect(teacher.getByRole('textbox', { name: /Title \(the students see it\)/ })).toHaveValue('Lesson 1');
  await expect(teacher.getByRole('textbox', { name: /Class code \(the dashboard/ })).toHaveValue('5H2');
  await expect(teacher.locator('li[data-level]')).toHaveCount(2);

  await shelf.getByRole('button', { name: 'Copy for another class…' }).click();
  await shelf.getByRole('textbox', { name: 'Title of the copy' }).fill('Lesson 1 for 5H3');
  await shelf.getByRole('textbox', { name: 'Class code' }).fill('5H3');
  await shelf.getByRole('button', { name: 'Make the copy' }).click();
  await expect(shelf.getByRole('listitem')).toHaveCount(2);
  await expect(teacher.getByRole('textbox', { name: /Class code \(the dashboard/ })).toHaveValue('5H3');
  await expect(teacher.locator('li[data-level]')).toHaveCount(2);
  await expect(shelf.getByRole('listitem').first()).toContainText('Lesson 1 for 5H3 · 5H3');

  const formLink = (await teacher.getByRole('link', { name: /This form, to bookmark/ }).getAttribute('href')) ?? '';
  expect(formLink).toMatch(/^#\/teacher\/a\/1\./);

  // Level 4 is locked in free play; its preview opens it at once and writes no progress.
  const preview = teacher.locator('li[data-level="04-shadows"]').getByRole('link', { name: 'Preview' });
  await expect(preview).toHaveAttribute('href', '#/preview/04-shadows');
  const before = await page.evaluate(() => Object.keys(localStorage).sort());
  await page.goto('./#/preview/04-shadows');
  await expect(page.locator('rt-preview-notice')).toContainText('Nothing is saved');
  await expect(page.locator('rt-lab').getByText('In the shadow').first()).toBeVisible();
  await page.waitForTimeout(500);
  const after = await page.evaluate(() => Object.keys(localStorage).filter((key) => key.startsWith('rtq.progress')));
  expect(after).toEqual(before.filter((key) => key.startsWith('rtq.progress')));

  // The form's own address fills it in a browser that kept nothing.
  await page.evaluate(() => localStorage.clear());
  await page.goto(`./${formLink}`);
  await expect(teacher.getByRole('textbox', { name: /Title \(the students see it\)/ })).toHaveValue('Lesson 1 for 5H3');
  await expect(teacher.locator('li[data-level]')).toHaveCount(2);
  await expect(shelf.getByRole('status')).toHaveText(/^Kept in this browser/);
});
