//! The project as a whole: the book's includes, the source layout, the scene files and their errors, the film and the main binary, the grader.

mod book;
mod figures;
mod film_and_main;
mod fuzz;
mod glossary;
mod grading;
mod hostile;
mod hostile_bvh;
mod layout;
mod live_student;
mod mutants;
mod non_square;
mod reports;
mod scene_docs;
mod scene_errors;
mod unit;
